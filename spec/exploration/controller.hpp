#pragma once
// @component Controller (thesis Controller FMU): two-phase unicycle point-to-point control.
//   inputs:  pose (x_m, y_m, theta_rad) from the Body; waypoint (xDesired, yDesired) and
//            onDestinationInput from the Environment
//   state:   maneuver (1 orient, 2 drive), onDestinationOutput, beta_rad
//   outputs: servo_left, servo_right in [-1, 1]; onDestinationOutput
//   no direct feedthrough: outputs are the state after the step.
//
// One step, with dx = xDesired - x, dy = yDesired - y, heading psi = theta + pi/2 (the Body's
// forward is (-sin theta, cos theta)):
//   idle (output 1) and input 1  -> accept the new waypoint: output 0, maneuver 1, servos 0
//   idle otherwise               -> servos 0
//   |dx| + |dy| < tolerance      -> arrived: maneuver 1, output 1, servos 0
//   maneuver 1: atan2 fix: unless |dx| and |dy| are both < tolerance, a delta below the
//               tolerance is taken as 0; beta = wrap(atan2(dy, dx) - psi);
//               |beta| < orient_tolerance -> maneuver 2
//   maneuver 2: beta = wrap(atan2(dy, dx) - psi); |beta| > reorient -> maneuver 1
//   v = 0 in maneuver 1; in maneuver 2 v = rho * k_v * (rho^2 cos beta + beta sin beta),
//   rho = sqrt(dx^2 + dy^2); w = -k_beta * beta
//   servo_left = v / R + (L / (2R)) w,  servo_right = -(v / R - (L / (2R)) w),  L = 2a
//   each servo saturated to [-1, 1], NaN to 0.
// wrap(x) is in (-pi, pi].
#include "spec/exploration/types.hpp"

namespace swarmcheck::exploration {

struct ControllerInputs {
  BodyState pose;
  Point_m waypoint;
  int32_t on_destination_input;
};

ControllerState initial_controller();

// The angle in (-pi, pi] equal to x modulo 2 pi (IEEE remainder, then -pi maps to pi).
double wrap_angle(double x_rad);

// Saturation of a servo command: [-1, 1], NaN to 0 (the thesis's clamp passes NaN through).
double saturate_servo(double u);

// The thesis's clamp, kept to show (and prove) where it fails: NaN passes through.
double thesis_clamp(double u);

ControllerState controller_step(const RobotParams& rp, const ControllerState& s,
                                const ControllerInputs& in);

}  // namespace swarmcheck::exploration
