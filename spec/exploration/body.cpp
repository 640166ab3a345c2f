#include "spec/exploration/body.hpp"

#include <cmath>

#include "spec/util/demand.hpp"

namespace swarmcheck::exploration {

namespace {
bool negative_zero(double v) { return v == 0 && std::signbit(v); }
}  // namespace

bool body_stays(const BodyState& s, double servo_left, double servo_right) {
  return servo_left == 0 && servo_right == 0 && !negative_zero(s.x_m) && !negative_zero(s.y_m) &&
         !negative_zero(s.theta_rad);
}

Heading heading_of(double theta_rad) { return Heading{std::cos(theta_rad), std::sin(theta_rad)}; }

BodyState body_step(const RobotParams& rp, const BodyState& s, double servo_left,
                    double servo_right, double dt_s) {
  return body_step_with_heading(rp, s, heading_of(s.theta_rad), servo_left, servo_right, dt_s).state;
}

BodyStep body_step_with_heading(const RobotParams& rp, const BodyState& s, const Heading& h,
                                double servo_left, double servo_right, double dt_s) {
  SWARM_DEMAND(dt_s > 0);
  SWARM_DEMAND(!std::isnan(servo_left) && !std::isnan(servo_right));
  const double rk = rp.wheel_radius_m * rp.motor_gain_rad_per_s;
  const double v = rk * (servo_left - servo_right) / 2;
  const double omega = -rk * (servo_left + servo_right) / (2 * rp.half_axle_m);
  BodyStep n;
  n.state.theta_rad = s.theta_rad + omega * dt_s;
  const bool same_theta = n.state.theta_rad == s.theta_rad &&
                          std::signbit(n.state.theta_rad) == std::signbit(s.theta_rad);
  n.heading = same_theta ? h : heading_of(n.state.theta_rad);
  if (std::fabs(omega * dt_s) < 1e-12) {
    n.state.x_m = s.x_m - v * dt_s * h.sin_theta;
    n.state.y_m = s.y_m + v * dt_s * h.cos_theta;
  } else {
    n.state.x_m = s.x_m + (v / omega) * (n.heading.cos_theta - h.cos_theta);
    n.state.y_m = s.y_m + (v / omega) * (n.heading.sin_theta - h.sin_theta);
  }
  return n;
}

}  // namespace swarmcheck::exploration
