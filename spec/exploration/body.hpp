#pragma once
// @component Body (DESIGN.md A9): differential drive, INTO-CPS line-follower Body_Block's
// steady state.
//   inputs:  servo_left, servo_right in [-1, 1]
//   state = outputs: x_m, y_m, theta_rad
//   v     = r K (uL - uR) / 2          (the right servo is mirrored)
//   omega = -r K (uL + uR) / (2 a)
//   forward is (-sin theta, cos theta); exact unicycle integration over dt with v and omega
//   held: theta' = theta + omega dt,
//         x' = x + (v / omega)(cos theta' - cos theta),  y' = y + (v / omega)(sin theta' - sin theta)
//   and, when |omega dt| < 1e-12 (where v / omega would lose every digit), the straight line
//         x' = x - v dt sin theta,  y' = y + v dt cos theta.
#include "spec/exploration/types.hpp"

namespace swarmcheck::exploration {

BodyState body_step(const RobotParams& rp, const BodyState& s, double servo_left,
                    double servo_right, double dt_s);

}  // namespace swarmcheck::exploration
