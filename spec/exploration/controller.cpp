#include "spec/exploration/controller.hpp"

#include <cmath>
#include <numbers>

#include "spec/util/demand.hpp"

namespace swarmcheck::exploration {
namespace {

constexpr double kPi = std::numbers::pi;

}  // namespace

template <class D>
typename D::Real saturate_servo_rule(const typename D::Real& u) {
  return num::select(num::is_nan(u), typename D::Real(0.0),
                     num::select(u > 1.0, typename D::Real(1.0), num::select(u < -1.0, typename D::Real(-1.0), u)));
}

template <class D>
typename D::Real thesis_clamp_rule(const typename D::Real& u) {
  return num::select(u > 1.0, typename D::Real(1.0), num::select(u < -1.0, typename D::Real(-1.0), u));
}

template <class D>
ServoPairT<D> servo_mix_rule(const ControllerParamsT<D>& p, const typename D::Real& v, const typename D::Real& w) {
  const typename D::Real r = p.wheel_radius_m;
  const typename D::Real l = 2.0 * p.half_axle_m;
  return {(1.0 / r) * v + (l / (2.0 * r)) * w, -((1.0 / r) * v - (l / (2.0 * r)) * w)};
}

template <class D>
DeltaT<D> atan2_fix_rule(const DeltaT<D>& d, const typename D::Real& tolerance_m) {
  // Near-zero deltas would flip atan2's sign as the body jitters in place.
  const typename D::Bool small_x = num::abs(d.dx) < tolerance_m;
  const typename D::Bool small_y = num::abs(d.dy) < tolerance_m;
  const typename D::Bool both = small_x && small_y;
  return {num::select(!both && small_x, typename D::Real(0.0), d.dx),
          num::select(!both && small_y, typename D::Real(0.0), d.dy)};
}

template <class D>
typename D::Real wrap_angle_rule(const typename D::Real& x_rad) {
  const typename D::Real r = num::remainder(x_rad, typename D::Real(2 * kPi));
  return num::select(r <= -kPi, r + 2 * kPi, r);
}

// Bearing error: the waypoint's direction minus the heading theta + pi/2, wrapped.
template <class D>
typename D::Real bearing_error_rule(const DeltaT<D>& d, const typename D::Real& theta_rad) {
  return wrap_angle_rule<D>(num::atan2(d.dy, d.dx) - theta_rad - kPi / 2);
}

template <class D>
typename D::Bool arrived_rule(const DeltaT<D>& d, const typename D::Real& tolerance_m) {
  return num::abs(d.dx) + num::abs(d.dy) < tolerance_m;
}

template <class D>
typename D::Real orientation_target_rule(const ControllerParamsT<D>& p, const DeltaT<D>& d,
                                         const typename D::Real& theta_rad) {
  (void)p;   // the raw deltas: the target is held while turning, so no deadband is needed against jitter
  return theta_rad + bearing_error_rule<D>(d, theta_rad);
}

template <class D>
typename D::Real turn_gain_rule(const ControllerParamsT<D>& p, const typename D::Real& step_s) {
  const typename D::Real cap = p.loop_gain / (p.motor_gain_rad_per_s * step_s);
  return num::select(p.k_beta < cap, p.k_beta, cap);
}

template <class D>
DriveT<D> drive_rule(const ControllerParamsT<D>& p, const ControllerCoreT<D>& s, const ControllerInputsT<D>& in,
                     const DeltaT<D>& d) {
  using Real = typename D::Real;
  using Bool = typename D::Bool;
  // Maneuver 2 steers on the live bearing; past `reorient` it turns in place again, towards a
  // target chosen now. Maneuver 1 turns towards the target it holds, whatever the pose reads.
  const Real live = bearing_error_rule<D>(d, in.theta_rad);
  const Bool reorient = s.driving && num::abs(live) > p.reorient_rad;
  const Bool orienting = !s.driving || reorient;
  const Real target = num::select(reorient, orientation_target_rule<D>(p, d, in.theta_rad), s.target_theta_rad);
  const Real beta = num::select(orienting, target - in.theta_rad, live);
  const Bool driving = num::select(orienting, num::abs(beta) < p.orient_tolerance_rad, Bool(true));
  const Real rho = num::sqrt(d.dx * d.dx + d.dy * d.dy);
  const Real drive = rho * p.k_v * (rho * rho * num::cos(beta) + beta * num::sin(beta));
  const Real v_max = p.loop_gain * rho / (p.motor_gain_rad_per_s * in.step_s);
  const Real v = num::select(driving, num::select(drive > v_max, v_max, drive), Real(0.0));
  const Real w = -turn_gain_rule<D>(p, in.step_s) * beta;
  const ServoPairT<D> mix = servo_mix_rule<D>(p, v, w);
  return DriveT<D>{ControllerCoreT<D>{Bool(false), driving, beta, saturate_servo_rule<D>(mix.left),
                                      saturate_servo_rule<D>(mix.right), target},
                   rho, v, w};
}

template <class D>
ControllerCoreT<D> controller_rule(const ControllerParamsT<D>& p, const ControllerCoreT<D>& s,
                                   const ControllerInputsT<D>& in) {
  using Real = typename D::Real;
  using Bool = typename D::Bool;
  const DeltaT<D> d{in.x_desired_m - in.x_m, in.y_desired_m - in.y_m};
  // Idle and told of a new waypoint: accept it (output 0, maneuver 1, servos 0) and choose the
  // heading to turn to from the pose and waypoint read now; idle: hold.
  const auto accept = [&] {
    return ControllerCoreT<D>{Bool(false), Bool(false), s.beta_rad, Real(0.0), Real(0.0),
                              orientation_target_rule<D>(p, d, in.theta_rad)};
  };
  const auto hold = [&] {
    return ControllerCoreT<D>{Bool(true), s.driving, s.beta_rad, Real(0.0), Real(0.0), s.target_theta_rad};
  };
  const auto idle_step = [&] { return num::branch(in.on_destination_input, accept, hold); };
  const auto busy_step = [&] {
    const auto arrived = [&] {
      return ControllerCoreT<D>{Bool(true), Bool(false), s.beta_rad, Real(0.0), Real(0.0), s.target_theta_rad};
    };
    const auto drive = [&] { return drive_rule<D>(p, s, in, d).next; };
    return num::branch(arrived_rule<D>(d, p.tolerance_m), arrived, drive);
  };
  return num::branch(s.idle, idle_step, busy_step);
}

#define SWARMCHECK_CONTROLLER_RULES(D)                                                                      \
  template D::Real saturate_servo_rule<D>(const D::Real&);                                                  \
  template D::Real thesis_clamp_rule<D>(const D::Real&);                                                    \
  template ServoPairT<D> servo_mix_rule<D>(const ControllerParamsT<D>&, const D::Real&, const D::Real&);    \
  template DeltaT<D> atan2_fix_rule<D>(const DeltaT<D>&, const D::Real&);                                   \
  template D::Real bearing_error_rule<D>(const DeltaT<D>&, const D::Real&);                                 \
  template D::Real orientation_target_rule<D>(const ControllerParamsT<D>&, const DeltaT<D>&, const D::Real&); \
  template D::Real turn_gain_rule<D>(const ControllerParamsT<D>&, const D::Real&);                          \
  template D::Bool arrived_rule<D>(const DeltaT<D>&, const D::Real&);                                       \
  template ControllerCoreT<D> controller_rule<D>(const ControllerParamsT<D>&, const ControllerCoreT<D>&,   \
                                                 const ControllerInputsT<D>&);                              \
  template DriveT<D> drive_rule<D>(const ControllerParamsT<D>&, const ControllerCoreT<D>&,                 \
                                   const ControllerInputsT<D>&, const DeltaT<D>&);
SWARMCHECK_CONTROLLER_RULES(num::Concrete)
SWARMCHECK_CONTROLLER_RULES(num::Symbolic)
#undef SWARMCHECK_CONTROLLER_RULES

ControllerParamsT<num::Concrete> controller_params(const RobotParams& rp) {
  return {rp.tolerance_m, rp.orient_tolerance_rad, rp.reorient_rad, rp.k_v, rp.k_beta,
          rp.wheel_radius_m, rp.half_axle_m, rp.motor_gain_rad_per_s, rp.loop_gain};
}

ControllerParamsT<num::Symbolic> symbolic_controller_params(const RobotParams& rp) {
  return {rp.tolerance_m, rp.orient_tolerance_rad, rp.reorient_rad, rp.k_v, rp.k_beta,
          rp.wheel_radius_m, rp.half_axle_m, rp.motor_gain_rad_per_s, rp.loop_gain};
}

ControllerState initial_controller() { return ControllerState{1, 1, 0.0, 0.0, 0.0, 0.0}; }

double wrap_angle(double x_rad) { return wrap_angle_rule<num::Concrete>(x_rad); }
double saturate_servo(double u) { return saturate_servo_rule<num::Concrete>(u); }
double thesis_clamp(double u) { return thesis_clamp_rule<num::Concrete>(u); }

ControllerState controller_step(const RobotParams& rp, const ControllerState& s,
                                const ControllerInputs& in) {
  SWARM_DEMAND(s.maneuver == 1 || s.maneuver == 2);
  SWARM_DEMAND(s.on_destination_output == 0 || s.on_destination_output == 1);
  SWARM_DEMAND(in.step_s > 0);
  const ControllerCoreT<num::Concrete> core{s.on_destination_output == 1, s.maneuver == 2, s.beta_rad,
                                            s.servo_left, s.servo_right, s.target_theta_rad};
  const ControllerCoreT<num::Concrete> n = controller_rule<num::Concrete>(
      controller_params(rp), core,
      {in.pose.x_m, in.pose.y_m, in.pose.theta_rad, in.waypoint[0], in.waypoint[1], in.on_destination_input == 1,
       in.step_s});
  return ControllerState{n.driving ? 2 : 1, n.idle ? 1 : 0, n.beta_rad, n.servo_left, n.servo_right,
                         n.target_theta_rad};
}

ControllerLocals controller_locals(const RobotParams& rp, const ControllerState& s, const ControllerInputs& in) {
  using C = num::Concrete;
  if (s.on_destination_output == 1) return {};
  const DeltaT<C> d{in.waypoint[0] - in.pose.x_m, in.waypoint[1] - in.pose.y_m};
  if (arrived_rule<C>(d, rp.tolerance_m)) return {};
  const ControllerCoreT<C> core{false, s.maneuver == 2, s.beta_rad, s.servo_left, s.servo_right,
                                s.target_theta_rad};
  const DriveT<C> r = drive_rule<C>(controller_params(rp), core,
                                    {in.pose.x_m, in.pose.y_m, in.pose.theta_rad, in.waypoint[0], in.waypoint[1],
                                     in.on_destination_input == 1, in.step_s},
                                    d);
  return {r.rho_m, r.v, r.w};
}

}  // namespace swarmcheck::exploration
