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

// Whether body_step(rp, s, servo_left, servo_right, dt_s) returns s exactly, known without the
// trigonometry: both servos are 0 and no coordinate is -0.0 (v and omega are then +-0, and adding
// +-0 leaves the bits of any value but -0.0). Callers skip the step of a robot standing still.
bool body_stays(const BodyState& s, double servo_left, double servo_right);

// cos and sin of a heading. A caller that keeps them from the step that produced theta (the same
// function of the same double gives the same bits) skips the trigonometry of a straight drive.
struct Heading {
  double cos_theta;
  double sin_theta;
};
Heading heading_of(double theta_rad);

struct BodyStep {
  BodyState state;
  Heading heading;   // heading_of(state.theta_rad)
};

// body_step, given h = heading_of(s.theta_rad); body_step is this with h computed.
BodyStep body_step_with_heading(const RobotParams& rp, const BodyState& s, const Heading& h,
                                double servo_left, double servo_right, double dt_s);

}  // namespace swarmcheck::exploration
