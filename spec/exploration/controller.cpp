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
DriveT<D> drive_rule(const ControllerParamsT<D>& p, const ControllerCoreT<D>& s, const ControllerInputsT<D>& in,
                     const DeltaT<D>& d) {
  using Real = typename D::Real;
  using Bool = typename D::Bool;
  // Maneuver 1 applies the atan2 fix; the deltas it leaves are the ones maneuver 2 drives on.
  const DeltaT<D> fixed = atan2_fix_rule<D>(d, p.tolerance_m);
  const DeltaT<D> used{num::select(s.driving, d.dx, fixed.dx), num::select(s.driving, d.dy, fixed.dy)};
  const Real beta = bearing_error_rule<D>(used, in.theta_rad);
  const Bool driving = num::select(s.driving, !(num::abs(beta) > p.reorient_rad),
                                   num::abs(beta) < p.orient_tolerance_rad);
  const Real rho = num::sqrt(used.dx * used.dx + used.dy * used.dy);
  const Real v = num::select(driving, rho * p.k_v * (rho * rho * num::cos(beta) + beta * num::sin(beta)),
                             Real(0.0));
  const Real w = -p.k_beta * beta;
  const ServoPairT<D> mix = servo_mix_rule<D>(p, v, w);
  return DriveT<D>{ControllerCoreT<D>{Bool(false), driving, beta, saturate_servo_rule<D>(mix.left),
                                      saturate_servo_rule<D>(mix.right)},
                   rho, v, w};
}

template <class D>
ControllerCoreT<D> controller_rule(const ControllerParamsT<D>& p, const ControllerCoreT<D>& s,
                                   const ControllerInputsT<D>& in) {
  using Real = typename D::Real;
  using Bool = typename D::Bool;
  // Idle and told of a new waypoint: accept it (output 0, maneuver 1), servos 0; idle: hold.
  const auto idle_step = [&] {
    return ControllerCoreT<D>{!in.on_destination_input,
                              num::select(in.on_destination_input, Bool(false), s.driving), s.beta_rad,
                              Real(0.0), Real(0.0)};
  };
  const auto busy_step = [&] {
    const DeltaT<D> d{in.x_desired_m - in.x_m, in.y_desired_m - in.y_m};
    const auto arrived = [&] { return ControllerCoreT<D>{Bool(true), Bool(false), s.beta_rad, Real(0.0), Real(0.0)}; };
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
  template D::Bool arrived_rule<D>(const DeltaT<D>&, const D::Real&);                                       \
  template ControllerCoreT<D> controller_rule<D>(const ControllerParamsT<D>&, const ControllerCoreT<D>&,   \
                                                 const ControllerInputsT<D>&);                              \
  template DriveT<D> drive_rule<D>(const ControllerParamsT<D>&, const ControllerCoreT<D>&,                 \
                                   const ControllerInputsT<D>&, const DeltaT<D>&);
SWARMCHECK_CONTROLLER_RULES(num::Concrete)
SWARMCHECK_CONTROLLER_RULES(num::Symbolic)
#undef SWARMCHECK_CONTROLLER_RULES

ControllerParamsT<num::Concrete> controller_params(const RobotParams& rp) {
  return {rp.tolerance_m, rp.orient_tolerance_rad, rp.reorient_rad, rp.k_v,
          rp.k_beta,      rp.wheel_radius_m,       rp.half_axle_m};
}

ControllerParamsT<num::Symbolic> symbolic_controller_params(const RobotParams& rp) {
  return {rp.tolerance_m, rp.orient_tolerance_rad, rp.reorient_rad, rp.k_v,
          rp.k_beta,      rp.wheel_radius_m,       rp.half_axle_m};
}

ControllerState initial_controller() { return ControllerState{1, 1, 0.0, 0.0, 0.0}; }

double wrap_angle(double x_rad) { return wrap_angle_rule<num::Concrete>(x_rad); }
double saturate_servo(double u) { return saturate_servo_rule<num::Concrete>(u); }
double thesis_clamp(double u) { return thesis_clamp_rule<num::Concrete>(u); }

ControllerState controller_step(const RobotParams& rp, const ControllerState& s,
                                const ControllerInputs& in) {
  SWARM_DEMAND(s.maneuver == 1 || s.maneuver == 2);
  SWARM_DEMAND(s.on_destination_output == 0 || s.on_destination_output == 1);
  const ControllerCoreT<num::Concrete> core{s.on_destination_output == 1, s.maneuver == 2, s.beta_rad,
                                            s.servo_left, s.servo_right};
  const ControllerCoreT<num::Concrete> n = controller_rule<num::Concrete>(
      controller_params(rp), core,
      {in.pose.x_m, in.pose.y_m, in.pose.theta_rad, in.waypoint[0], in.waypoint[1], in.on_destination_input == 1});
  ControllerState out = s;
  out.maneuver = n.driving ? 2 : 1;
  out.on_destination_output = n.idle ? 1 : 0;
  out.beta_rad = n.beta_rad;
  out.servo_left = n.servo_left;
  out.servo_right = n.servo_right;
  return out;
}

ControllerLocals controller_locals(const RobotParams& rp, const ControllerState& s, const ControllerInputs& in) {
  using C = num::Concrete;
  if (s.on_destination_output == 1) return {};
  const DeltaT<C> d{in.waypoint[0] - in.pose.x_m, in.waypoint[1] - in.pose.y_m};
  if (arrived_rule<C>(d, rp.tolerance_m)) return {};
  const ControllerCoreT<C> core{false, s.maneuver == 2, s.beta_rad, s.servo_left, s.servo_right};
  const DriveT<C> r = drive_rule<C>(controller_params(rp), core,
                                    {in.pose.x_m, in.pose.y_m, in.pose.theta_rad, in.waypoint[0], in.waypoint[1],
                                     in.on_destination_input == 1},
                                    d);
  return {r.rho_m, r.v, r.w};
}

}  // namespace swarmcheck::exploration
