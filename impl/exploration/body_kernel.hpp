#pragma once
// The Body step of spec/exploration/body.hpp, bit for bit, with cos and sin of the heading kept
// from the step that produced it: the same function of the same double gives the same bits, and
// a body driving straight (omega = 0, the saturated case) then needs no trigonometry at all.
#include <cmath>

#include "spec/exploration/types.hpp"

namespace swarmcheck::impl {

struct Heading {
  double cos_theta;
  double sin_theta;
};

inline Heading heading_of(double theta_rad) { return Heading{std::cos(theta_rad), std::sin(theta_rad)}; }

// Same operations, in the same order, as exploration::body_step.
inline void body_step_cached(const exploration::RobotParams& rp, exploration::BodyState& s, Heading& h,
                             double servo_left, double servo_right, double dt_s) {
  const double rk = rp.wheel_radius_m * rp.motor_gain_rad_per_s;
  const double v = rk * (servo_left - servo_right) / 2;
  const double omega = -rk * (servo_left + servo_right) / (2 * rp.half_axle_m);
  const double theta1 = s.theta_rad + omega * dt_s;
  if (std::fabs(omega * dt_s) < 1e-12) {
    s.x_m = s.x_m - v * dt_s * h.sin_theta;
    s.y_m = s.y_m + v * dt_s * h.cos_theta;
    if (theta1 != s.theta_rad || std::signbit(theta1) != std::signbit(s.theta_rad)) h = heading_of(theta1);
  } else {
    const Heading h1 = heading_of(theta1);
    s.x_m = s.x_m + (v / omega) * (h1.cos_theta - h.cos_theta);
    s.y_m = s.y_m + (v / omega) * (h1.sin_theta - h.sin_theta);
    h = h1;
  }
  s.theta_rad = theta1;
}

}  // namespace swarmcheck::impl
