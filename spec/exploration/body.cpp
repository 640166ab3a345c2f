#include "spec/exploration/body.hpp"

#include <cmath>

#include "spec/util/demand.hpp"

namespace swarmcheck::exploration {

BodyState body_step(const RobotParams& rp, const BodyState& s, double servo_left,
                    double servo_right, double dt_s) {
  SWARM_DEMAND(dt_s > 0);
  SWARM_DEMAND(!std::isnan(servo_left) && !std::isnan(servo_right));
  const double rk = rp.wheel_radius_m * rp.motor_gain_rad_per_s;
  const double v = rk * (servo_left - servo_right) / 2;
  const double omega = -rk * (servo_left + servo_right) / (2 * rp.half_axle_m);
  BodyState n;
  if (std::fabs(omega * dt_s) < 1e-12) {
    n.theta_rad = s.theta_rad + omega * dt_s;
    n.x_m = s.x_m - v * dt_s * std::sin(s.theta_rad);
    n.y_m = s.y_m + v * dt_s * std::cos(s.theta_rad);
  } else {
    n.theta_rad = s.theta_rad + omega * dt_s;
    n.x_m = s.x_m + (v / omega) * (std::cos(n.theta_rad) - std::cos(s.theta_rad));
    n.y_m = s.y_m + (v / omega) * (std::sin(n.theta_rad) - std::sin(s.theta_rad));
  }
  return n;
}

}  // namespace swarmcheck::exploration
