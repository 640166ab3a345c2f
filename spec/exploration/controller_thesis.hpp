#pragma once
// @component Controller `thesis`: thesis A's published UController FMU (PVSio-web,
// UController/fmu-pvs/misraC/UController.c), as its binary computes it with the INTO-CPS engine's
// start values (../shared/thesis-intocps.md). Kept to reproduce the published system, bugs
// included; the default controller (controller.hpp) departs from it (spec/SPEC.md section 11).
//   inputs:  x, y, phi (the Body's robot_x, robot_y, robot_theta), xDesired, yDesired,
//            onDestinationInput
//   state:   maneuver (2 at start: the C init() sets it and the engine's start value never reaches
//            it), onDestinationOutput (0 at start), beta; outputs servoLeft, servoRight
// One tick per step:
//   onDestinationInput 1        -> onDestinationOutput 0, servos 0 (the Environment has planned)
//   onDestinationOutput 1       -> servos 0 (waiting)
//   else dX = x - xDesired, dY = y - yDesired (robot minus waypoint):
//     maneuver 2: beta = |atan2(dY, dX) - phi + pi/2| (no wrap); |dX| + |dY| < 0.3 -> maneuver 1,
//                 onDestinationOutput 1 (arrived; the servos are still computed below)
//     maneuver 1: unless |dX| < 0.2 and |dY| < 0.2, a delta with |d| < 0.2 is 0;
//                 beta = atan2(dY, dX) - phi + pi/2 (no wrap); |beta| < 0.01 -> maneuver 2
//     v = 0 in maneuver 1, else rho k_v (pow(rho, 2) cos beta + beta sin beta),
//         rho = sqrt(pow(dX, 2) + pow(dY, 2)) of the deltas as they now are
//     w = -k_beta beta; servoLeft = clamp((1/R) v + (L/(2R)) w),
//     servoRight = clamp(-((1/R) v - (L/(2R)) w)), clamp the thesis's (NaN passes through)
// Constants: L = 0.052f, R = 0.032f (float literals widened to double), k_beta = 0.2 and
// k_v = 1 as the engine writes their start values (the C literal 0.2f would give 0.20000000298...).
#include "spec/exploration/controller.hpp"
#include "spec/exploration/types.hpp"
#include "spec/util/num.hpp"

namespace swarmcheck::exploration {

template <class D>
struct ThesisControllerParamsT {
  typename D::Real k_beta, k_v, wheel_distance_m, wheel_radius_m, deadband_m, arrival_m, orient_tolerance_rad;
};

struct ThesisControllerParams {
  double k_beta = 0.2;                                   // the engine's start value
  double k_v = 1.0;
  double wheel_distance_m = static_cast<double>(0.052f);   // L
  double wheel_radius_m = static_cast<double>(0.032f);     // R
  double deadband_m = 0.2;                               // TOLLERANCE of the atan2 fix
  double arrival_m = 0.3;                                // |dX| + |dY| < this: arrived
  double orient_tolerance_rad = 0.01;
};

template <class D>
ThesisControllerParamsT<D> thesis_controller_params_t(const ThesisControllerParams& p) {
  return {p.k_beta, p.k_v, p.wheel_distance_m, p.wheel_radius_m, p.deadband_m, p.arrival_m, p.orient_tolerance_rad};
}

// One tick, over a domain (controller_thesis.cpp instantiates it for Concrete and Symbolic). The
// core's `idle` is onDestinationOutput == 1, `driving` maneuver == 2; target_theta_rad is unused.
template <class D>
ControllerCoreT<D> thesis_controller_rule(const ThesisControllerParamsT<D>& p, const ControllerCoreT<D>& s,
                                          const ControllerInputsT<D>& in);

ControllerState initial_thesis_controller();
ControllerState thesis_controller_step(const ThesisControllerParams& p, const ControllerState& s,
                                       const ControllerInputs& in);

// What thesis_controller_step(p, s, in) computed on the way: rho (m), v and w (all 0 when the step
// was no tick): the UController FMU's rho, v and w.
ControllerLocals thesis_controller_locals(const ThesisControllerParams& p, const ControllerState& s,
                                          const ControllerInputs& in);

}  // namespace swarmcheck::exploration
