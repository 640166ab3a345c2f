#pragma once
// @component Controller `swarmcheck` (the default): two-phase unicycle point-to-point control, the
// thesis Controller FMU's law with the departures of spec/SPEC.md section 11 (the published one is
// controller_thesis.hpp).
//   inputs:  pose (x_m, y_m, theta_rad) from the Body; waypoint (xDesired, yDesired) and
//            onDestinationInput from the Environment; the step dt the outputs will be held for
//   state:   maneuver (1 orient, 2 drive), onDestinationOutput, beta_rad, target_theta_rad
//   outputs: servo_left, servo_right in [-1, 1]; onDestinationOutput
//   no direct feedthrough: outputs are the state after the step.
//
// One step, with dx = xDesired - x, dy = yDesired - y, heading psi = theta + pi/2 (the Body's
// forward is (-sin theta, cos theta)), wrap(x) in (-pi, pi]:
//   idle (output 1) and input 1  -> accept the new waypoint: output 0, maneuver 1, servos 0, and
//                                   target := the orientation target of the pose and waypoint read
//   idle otherwise               -> servos 0
//   |dx| + |dy| < tolerance      -> arrived: maneuver 1, output 1, servos 0
//   maneuver 1 (orient): beta = target - theta (the target stays as chosen: turning in place moves
//               the Body's reported point, which must not move the target);
//               |beta| < orient_tolerance -> maneuver 2
//   maneuver 2 (drive): beta = wrap(atan2(dy, dx) - psi); |beta| > reorient -> maneuver 1 with
//               target := the orientation target of this pose, beta = target - theta
//   orientation target = theta + wrap(atan2(dy, dx) - psi), of the deltas as read (no atan2-fix
//               deadband: the target is held while turning, so a reading's jitter cannot flip it;
//               the deadband only added re-orientations, measured on the leg property's legs)
//   gain caps: k = min(k_beta, g / (K dt)), vmax = g rho / (K dt), g = loop_gain
//   v = 0 in maneuver 1; in maneuver 2 v = min(rho k_v (rho^2 cos beta + beta sin beta), vmax),
//   rho = sqrt(dx^2 + dy^2); w = -k beta
//   servo_left = v / R + (L / (2R)) w,  servo_right = -(v / R - (L / (2R)) w),  L = 2a
//   each servo saturated to [-1, 1], NaN to 0.
#include "spec/exploration/types.hpp"
#include "spec/util/num.hpp"

namespace swarmcheck::exploration {

// ---- The rules, once, over a domain D (spec/util/num.hpp): controller.cpp instantiates them
// for num::Concrete (what runs) and num::Symbolic (what proofs/ proves). ----

template <class D>
struct ControllerParamsT {   // the RobotParams a controller step reads
  typename D::Real tolerance_m, orient_tolerance_rad, reorient_rad, k_v, k_beta, wheel_radius_m,
      half_axle_m, motor_gain_rad_per_s, loop_gain;
};

template <class D>
struct ControllerCoreT {     // ControllerState with its two flags as booleans
  typename D::Bool idle;     // onDestinationOutput == 1
  typename D::Bool driving;  // maneuver == 2
  typename D::Real beta_rad, servo_left, servo_right, target_theta_rad;
};

template <class D>
struct ControllerInputsT {
  typename D::Real x_m, y_m, theta_rad, x_desired_m, y_desired_m;
  typename D::Bool on_destination_input;
  typename D::Real step_s;   // the step the outputs are held for, > 0
};

template <class D>
struct ServoPairT {
  typename D::Real left, right;
};

template <class D>
struct DeltaT {
  typename D::Real dx, dy;
};

// Saturation of a servo command: [-1, 1], NaN to 0.
template <class D>
typename D::Real saturate_servo_rule(const typename D::Real& u);
// The thesis's clamp (if (u > 1) u = 1; else if (u < -1) u = -1;): NaN passes through.
template <class D>
typename D::Real thesis_clamp_rule(const typename D::Real& u);
// The unsaturated servo commands of a linear command v and a turn command w.
template <class D>
ServoPairT<D> servo_mix_rule(const ControllerParamsT<D>& p, const typename D::Real& v,
                             const typename D::Real& w);
// The atan2 fix of maneuver 1: unless both deltas are below the tolerance, a delta below it is 0.
template <class D>
DeltaT<D> atan2_fix_rule(const DeltaT<D>& d, const typename D::Real& tolerance_m);
// wrap(atan2(dy, dx) - theta - pi/2), in (-pi, pi].
template <class D>
typename D::Real bearing_error_rule(const DeltaT<D>& d, const typename D::Real& theta_rad);
// The heading maneuver 1 turns to from heading theta: theta + bearing_error_rule(atan2 fix of d).
template <class D>
typename D::Real orientation_target_rule(const ControllerParamsT<D>& p, const DeltaT<D>& d,
                                         const typename D::Real& theta_rad);
// The turn gain: min(k_beta, loop_gain / (K dt)).
template <class D>
typename D::Real turn_gain_rule(const ControllerParamsT<D>& p, const typename D::Real& step_s);
// Arrival: |dx| + |dy| < tolerance.
template <class D>
typename D::Bool arrived_rule(const DeltaT<D>& d, const typename D::Real& tolerance_m);
// Maneuvers 1 and 2 of a busy controller that has not arrived: the next core, with the distance
// rho, linear command v and turn command w it computed on the way (the FMU shows them).
template <class D>
struct DriveT {
  ControllerCoreT<D> next;
  typename D::Real rho_m, v, w;
};
template <class D>
DriveT<D> drive_rule(const ControllerParamsT<D>& p, const ControllerCoreT<D>& s, const ControllerInputsT<D>& in,
                     const DeltaT<D>& d);
// One controller step (the whole of controller_step, on booleans).
template <class D>
ControllerCoreT<D> controller_rule(const ControllerParamsT<D>& p, const ControllerCoreT<D>& s,
                                   const ControllerInputsT<D>& in);

ControllerParamsT<num::Concrete> controller_params(const RobotParams& rp);
// The same parameters as symbolic literals (the doubles the code reads).
ControllerParamsT<num::Symbolic> symbolic_controller_params(const RobotParams& rp);

template <class D>
ControllerCoreT<D> merge(const typename D::Bool& c, const ControllerCoreT<D>& a, const ControllerCoreT<D>& b) {
  return {num::select(c, a.idle, b.idle), num::select(c, a.driving, b.driving),
          num::select(c, a.beta_rad, b.beta_rad), num::select(c, a.servo_left, b.servo_left),
          num::select(c, a.servo_right, b.servo_right), num::select(c, a.target_theta_rad, b.target_theta_rad)};
}
inline ControllerCoreT<num::Symbolic> merge(const sym::Bool& c, const ControllerCoreT<num::Symbolic>& a,
                                            const ControllerCoreT<num::Symbolic>& b) {
  return merge<num::Symbolic>(c, a, b);
}

// ---- The concrete API (what model/ and impl/ call). ----

struct ControllerInputs {
  BodyState pose;
  Point_m waypoint;
  int32_t on_destination_input;
  double step_s;   // the step the outputs are held for (the master's step_size), > 0
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

// What controller_step(rp, s, in) computed on the way: rho (m), v and w of drive_rule; all 0 when
// the step was idle or an arrival (the thesis Controller FMU's local variables).
struct ControllerLocals {
  double rho_m = 0, v = 0, w = 0;
};
ControllerLocals controller_locals(const RobotParams& rp, const ControllerState& s, const ControllerInputs& in);

}  // namespace swarmcheck::exploration
