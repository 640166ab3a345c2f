#include "spec/exploration/controller_thesis.hpp"

#include <cmath>
#include <numbers>

#include "spec/util/demand.hpp"

namespace swarmcheck::exploration {
namespace {
constexpr double kThesisPi = std::numbers::pi;   // M_PI
}  // namespace

template <class D>
ControllerCoreT<D> thesis_controller_rule(const ThesisControllerParamsT<D>& p, const ControllerCoreT<D>& s,
                                          const ControllerInputsT<D>& in) {
  using Real = typename D::Real;
  using Bool = typename D::Bool;
  const auto told = [&] {   // the Environment has planned: lower the output, stop
    return ControllerCoreT<D>{Bool(false), s.driving, s.beta_rad, Real(0.0), Real(0.0), s.target_theta_rad};
  };
  const auto waiting = [&] {
    return ControllerCoreT<D>{Bool(true), s.driving, s.beta_rad, Real(0.0), Real(0.0), s.target_theta_rad};
  };
  const auto tick = [&] {
    const Real dx = in.x_m - in.x_desired_m;   // robot minus waypoint
    const Real dy = in.y_m - in.y_desired_m;
    // Maneuver 2: the absolute bearing, and arrival.
    const Real beta2 = num::abs(num::atan2(dy, dx) - in.theta_rad + kThesisPi / 2);
    const Bool arrived = num::abs(dx) + num::abs(dy) < p.arrival_m;
    // Maneuver 1: the atan2 fix with the deadband (symmetric in the deltas' signs), the signed bearing.
    const DeltaT<D> fixed = atan2_fix_rule<D>(DeltaT<D>{dx, dy}, p.deadband_m);
    const Real fx = fixed.dx;
    const Real fy = fixed.dy;
    const Real beta1 = num::atan2(fy, fx) - in.theta_rad + kThesisPi / 2;
    const Bool was_driving = s.driving;
    const Real beta = num::select(was_driving, beta2, beta1);
    const Bool idle = was_driving && arrived;
    const Bool driving = num::select(was_driving, !arrived, num::abs(beta1) < p.orient_tolerance_rad);
    // v and w with the maneuver as it now is, from the deltas as they now are.
    const Real ux = num::select(was_driving, dx, fx);
    const Real uy = num::select(was_driving, dy, fy);
    const Real rho = num::sqrt(num::pow(ux, Real(2.0)) + num::pow(uy, Real(2.0)));
    const Real v = num::select(driving, rho * p.k_v * (num::pow(rho, Real(2.0)) * num::cos(beta) + beta * num::sin(beta)),
                               Real(0.0));
    const Real w = -p.k_beta * beta;
    const Real r = p.wheel_radius_m;
    const Real l = p.wheel_distance_m;
    const Real left = (1.0 / r) * v + (l / (2.0 * r)) * w;
    const Real right = -((1.0 / r) * v - (l / (2.0 * r)) * w);
    return ControllerCoreT<D>{idle, driving, beta, thesis_clamp_rule<D>(left), thesis_clamp_rule<D>(right),
                              s.target_theta_rad};
  };
  const auto busy = [&] { return num::branch(s.idle, waiting, tick); };
  return num::branch(in.on_destination_input, told, busy);
}

template ControllerCoreT<num::Concrete> thesis_controller_rule<num::Concrete>(
    const ThesisControllerParamsT<num::Concrete>&, const ControllerCoreT<num::Concrete>&,
    const ControllerInputsT<num::Concrete>&);
template ControllerCoreT<num::Symbolic> thesis_controller_rule<num::Symbolic>(
    const ThesisControllerParamsT<num::Symbolic>&, const ControllerCoreT<num::Symbolic>&,
    const ControllerInputsT<num::Symbolic>&);

ControllerState initial_thesis_controller() { return ControllerState{2, 0, 0.0, 0.0, 0.0, 0.0}; }

ControllerState thesis_controller_step(const ThesisControllerParams& p, const ControllerState& s,
                                       const ControllerInputs& in) {
  SWARM_DEMAND(s.maneuver == 1 || s.maneuver == 2);
  SWARM_DEMAND(s.on_destination_output == 0 || s.on_destination_output == 1);
  using C = num::Concrete;
  const ControllerCoreT<C> core{s.on_destination_output == 1, s.maneuver == 2, s.beta_rad, s.servo_left,
                                s.servo_right, s.target_theta_rad};
  const ControllerCoreT<C> n = thesis_controller_rule<C>(
      thesis_controller_params_t<C>(p), core,
      {in.pose.x_m, in.pose.y_m, in.pose.theta_rad, in.waypoint[0], in.waypoint[1], in.on_destination_input == 1,
       in.step_s});
  return ControllerState{n.driving ? 2 : 1, n.idle ? 1 : 0, n.beta_rad, n.servo_left, n.servo_right,
                         n.target_theta_rad};
}

}  // namespace swarmcheck::exploration

namespace swarmcheck::exploration {

ControllerLocals thesis_controller_locals(const ThesisControllerParams& p, const ControllerState& s,
                                          const ControllerInputs& in) {
  // The tick of thesis_controller_rule again, for what it does not return: rho, v, w (0 when the
  // step was no tick). tests/exploration/controller_thesis_test.cpp checks that these v and w give
  // the rule's servos.
  if (in.on_destination_input == 1 || s.on_destination_output == 1) return {};
  const double dx = in.pose.x_m - in.waypoint[0];
  const double dy = in.pose.y_m - in.waypoint[1];
  const bool was_driving = s.maneuver == 2;
  const DeltaT<num::Concrete> fixed = atan2_fix_rule<num::Concrete>(DeltaT<num::Concrete>{dx, dy}, p.deadband_m);
  const double beta1 = std::atan2(fixed.dy, fixed.dx) - in.pose.theta_rad + kThesisPi / 2;
  const double beta = was_driving ? std::fabs(std::atan2(dy, dx) - in.pose.theta_rad + kThesisPi / 2) : beta1;
  const bool driving = was_driving ? !(std::fabs(dx) + std::fabs(dy) < p.arrival_m) : std::fabs(beta1) < p.orient_tolerance_rad;
  const double ux = was_driving ? dx : fixed.dx;
  const double uy = was_driving ? dy : fixed.dy;
  ControllerLocals l;
  l.rho_m = std::sqrt(std::pow(ux, 2.0) + std::pow(uy, 2.0));
  l.v = driving ? l.rho_m * p.k_v * (std::pow(l.rho_m, 2.0) * std::cos(beta) + beta * std::sin(beta)) : 0.0;
  l.w = -p.k_beta * beta;
  return l;
}

}  // namespace swarmcheck::exploration
