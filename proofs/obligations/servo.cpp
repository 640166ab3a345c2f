// Obligations servo-saturation (the spec's saturation), servo-thesis-clamp (the thesis's) and
// servo-controller-range (what the controller outputs, through controller_rule and drive_rule).
#include "proofs/obligations/servo.hpp"

#include <cmath>
#include <cstdint>
#include <fmt/format.h>

#include <optional>

#include "proofs/obligations/handshake_system.hpp"
#include "proofs/obligations/obligation.hpp"
#include "spec/exploration/controller.hpp"

namespace swarmcheck::proofs {
namespace servo {

Commands commands(Translator& t, const exploration::RobotParams& rp, const sym::Real& v, const sym::Real& w,
                  Clamp clamp) {
  using S = num::Symbolic;
  const exploration::ServoPairT<S> mix =
      exploration::servo_mix_rule<S>(exploration::symbolic_controller_params(rp), v, w);
  auto sat = clamp == Clamp::spec ? exploration::saturate_servo_rule<S> : exploration::thesis_clamp_rule<S>;
  const char* name = clamp == Clamp::spec ? "exploration::saturate_servo_rule" : "exploration::thesis_clamp_rule";
  return Commands{t(num::traced(name, sat(num::traced("exploration::servo_mix_rule", mix.left)))),
                  t(num::traced(name, sat(num::traced("exploration::servo_mix_rule", mix.right))))};
}

}  // namespace servo

namespace {

using S = num::Symbolic;
using C = num::Concrete;
using ConcreteClamp = double (*)(double);

z3::expr in_range(z3::context& c, const z3::expr& s) {
  return !s.mk_is_nan() && s >= c.fpa_val(-1.0) && s <= c.fpa_val(1.0);
}

// Is there a double v (linear command) and w (turn command), NaN and infinities included,
// for which a clamped servo command is NaN or outside [-1, 1]?
Outcome check_clamp(Session& session, servo::Clamp clamp, ConcreteClamp concrete, const char* label) {
  z3::context& c = session.ctx();
  const exploration::RobotParams rp;
  Translator t(session, RealTheory::fp64);
  const sym::Real sv = sym::Real::var("v"), sw = sym::Real::var("w");
  const z3::expr v = t(sv), w = t(sw);
  const servo::Commands m = servo::commands(t, rp, sv, sw, clamp);
  z3::solver s = session.make_solver();
  s.add(t.side_conditions());
  s.add(!(in_range(c, m.left) && in_range(c, m.right)));
  switch (session.check(s, label)) {
    case z3::unsat:
      return {Verdict::proved, "unsat: no double v, w (NaN and infinities included) gives a "
                               "servo command outside [-1, 1]", {}};
    case z3::sat: {
      const z3::model model = s.get_model();
      const double vv = model_double(model, v), ww = model_double(model, w);
      // Replay the counterexample through the executed code: the concrete instantiation.
      const auto mix = exploration::servo_mix_rule<C>(exploration::controller_params(rp), vv, ww);
      const double left = concrete(mix.left);
      const double right = concrete(mix.right);
      const bool confirmed = !(left >= -1 && left <= 1 && right >= -1 && right <= 1);
      return {confirmed ? Verdict::refuted : Verdict::unknown,
              fmt::format("sat: v = {}, w = {} gives servo_left = {}, servo_right = {} ({})", vv,
                          ww, left, right,
                          confirmed ? "confirmed by running the executed code"
                                    : "NOT reproduced by the executed code: a spurious counterexample"),
              {}};
    }
    default:
      return {Verdict::unknown, "z3: unknown (" + s.reason_unknown() + ")", {}};
  }
}

// The controller's state and inputs as free doubles and booleans.
struct FreeController {
  exploration::ControllerCoreT<S> state{sym::Bool::var("idle"), sym::Bool::var("driving"), sym::Real::var("beta"),
                                        sym::Real::var("servo_left"), sym::Real::var("servo_right"),
                                        sym::Real::var("target")};
  exploration::ControllerInputsT<S> in{sym::Real::var("x"),         sym::Real::var("y"),
                                       sym::Real::var("theta"),     sym::Real::var("x_desired"),
                                       sym::Real::var("y_desired"), sym::Bool::var("on_destination_input"),
                                       sym::Real::var("step")};
};

// The model's controller state and inputs, as controller_step takes them.
struct ConcreteController {
  exploration::ControllerState state;
  exploration::ControllerInputs in;
  std::string text() const {
    return fmt::format("maneuver {}, onDestinationOutput {}, beta {}, pose ({}, {}, {}), waypoint ({}, {}), "
                       "onDestinationInput {}",
                       state.maneuver, state.on_destination_output, state.beta_rad, in.pose.x_m, in.pose.y_m,
                       in.pose.theta_rad, in.waypoint[0], in.waypoint[1], in.on_destination_input);
  }
};

ConcreteController concrete_of(const z3::model& m, Translator& t, const FreeController& f) {
  auto d = [&](const sym::Real& x) { return model_double(m, t(x)); };
  auto b = [&](const sym::Bool& x) { return m.eval(t(x), true).is_true(); };
  ConcreteController c;
  c.state = {b(f.state.driving) ? 2 : 1, b(f.state.idle) ? 1 : 0, d(f.state.beta_rad), d(f.state.servo_left),
             d(f.state.servo_right), d(f.state.target_theta_rad)};
  c.in = {{d(f.in.x_m), d(f.in.y_m), d(f.in.theta_rad)}, {d(f.in.x_desired_m), d(f.in.y_desired_m)},
          b(f.in.on_destination_input) ? 1 : 0, d(f.in.step_s)};
  return c;
}

// Asks whether a servo command pair can leave [-1, 1] (or be NaN): first with every arithmetic
// operation abstracted to a free double (the saturation alone must then keep the range: quick);
// if that abstraction has a model, exactly over IEEE doubles (a counterexample is then a model of
// the code, for the replay). nullopt: in range.
std::optional<z3::model> out_of_range(Session& session, const sym::Real& left, const sym::Real& right,
                                      const std::string& label, z3::check_result& answer, std::string& reason) {
  for (const bool abstracted : {true, false}) {
    Translator t(session, RealTheory::fp64);
    t.abstract_real_arithmetic(abstracted);
    z3::solver s = session.make_solver();
    const z3::expr l = t(left), r = t(right);
    s.add(t.side_conditions());
    s.add(!(in_range(session.ctx(), l) && in_range(session.ctx(), r)));
    answer = session.check(s, abstracted ? label + "-abstract" : label);
    if (answer == z3::unsat) return std::nullopt;
    if (answer != z3::sat) {
      reason = s.reason_unknown();
      return std::nullopt;
    }
    if (!abstracted) return s.get_model();
  }
  return std::nullopt;
}

// The executed drive_rule over a fixed grid of states and inputs (both maneuvers, headings round
// the circle, deltas from 0 to 1e6, steps 0.1 and 0.5): an input on which it leaves [-1, 1] is a
// counterexample by execution. Finding none concludes nothing: the queries below decide.
std::optional<ConcreteController> search_drive_rule(const exploration::RobotParams& rp) {
  const exploration::ControllerParamsT<C> p = exploration::controller_params(rp);
  constexpr double kQuarter = 0.78539816339744828;
  const double headings[] = {0.0, kQuarter, -kQuarter, 2 * kQuarter, -2 * kQuarter, 3 * kQuarter, -3 * kQuarter,
                             4 * kQuarter, 1e-3, -1e-3};
  const double deltas[] = {0.0, 1e-3, -1e-3, 0.04, -0.04, 0.3, -0.3, 2.0, -2.0, 50.0, -50.0, 1e6, -1e6};
  const double angles[] = {0.0, 1.0, -2.0};
  for (const bool driving : {false, true})
    for (const double theta : headings)
      for (const double dx : deltas)
        for (const double dy : deltas)
          for (const double beta : angles)
            for (const double target : angles)
              for (const double step : {0.1, 0.5}) {
                const exploration::ControllerCoreT<C> core{false, driving, beta, 0.0, 0.0, target};
                const exploration::DriveT<C> out =
                    exploration::drive_rule<C>(p, core, {0.0, 0.0, theta, dx, dy, false, step}, {dx, dy});
                if (out.next.servo_left >= -1 && out.next.servo_left <= 1 && out.next.servo_right >= -1 &&
                    out.next.servo_right <= 1)
                  continue;
                ConcreteController c;
                c.state = {driving ? 2 : 1, 0, beta, 0.0, 0.0, target};
                c.in = {{0.0, 0.0, theta}, {dx, dy}, 0, step};
                return c;
              }
  return std::nullopt;
}

// The servo commands of any controller state and any inputs (doubles, NaN and infinities
// included), through the spec's controller_rule (and, its moving maneuvers, drive_rule), are in
// [-1, 1]. The previous commands are any doubles too: nothing is assumed of the state.
Outcome check_controller(Session& session) {
  const exploration::RobotParams rp;
  const exploration::ControllerParamsT<S> p = exploration::symbolic_controller_params(rp);
  const FreeController f;
  Translator t(session, RealTheory::fp64);   // reads the model's inputs
  z3::check_result answer = z3::unknown;
  std::string reason;
  // First the executed drive_rule over a grid of inputs (milliseconds): an input it takes out of
  // the range is a counterexample by execution, which the exact query over free doubles may not
  // reach within the resource limit (a square root and several products: it did not, for a
  // right servo left unsaturated).
  if (const auto found = search_drive_rule(rp)) {
    const exploration::ControllerCoreT<C> core{false, found->state.maneuver == 2, found->state.beta_rad, 0.0, 0.0,
                                               found->state.target_theta_rad};
    const exploration::DriveT<C> out = exploration::drive_rule<C>(
        exploration::controller_params(rp), core,
        {0.0, 0.0, found->in.pose.theta_rad, found->in.waypoint[0], found->in.waypoint[1], false, found->in.step_s},
        {found->in.waypoint[0], found->in.waypoint[1]});
    return {Verdict::refuted,
            fmt::format("drive_rule run on a grid of inputs: {} commands servo_left = {}, servo_right = {} (confirmed "
                        "by running drive_rule: a counterexample by execution)",
                        found->text(), out.next.servo_left, out.next.servo_right),
            {}};
  }
  // drive_rule: the maneuvers' commands, for any deltas.
  const exploration::DeltaT<S> d{f.in.x_desired_m - f.in.x_m, f.in.y_desired_m - f.in.y_m};
  const exploration::DriveT<S> drive = exploration::drive_rule<S>(p, f.state, f.in, d);
  if (const auto m = out_of_range(session, num::traced("exploration::drive_rule", drive.next.servo_left),
                                  num::traced("exploration::drive_rule", drive.next.servo_right), "drive-rule", answer,
                                  reason)) {
    const ConcreteController cc = concrete_of(*m, t, f);
    const exploration::ControllerCoreT<C> core{false, cc.state.maneuver == 2, cc.state.beta_rad, cc.state.servo_left,
                                               cc.state.servo_right, cc.state.target_theta_rad};
    const exploration::DriveT<C> out = exploration::drive_rule<C>(
        exploration::controller_params(rp), core,
        {cc.in.pose.x_m, cc.in.pose.y_m, cc.in.pose.theta_rad, cc.in.waypoint[0], cc.in.waypoint[1],
         cc.in.on_destination_input == 1, cc.in.step_s},
        {cc.in.waypoint[0] - cc.in.pose.x_m, cc.in.waypoint[1] - cc.in.pose.y_m});
    const bool confirmed = !(out.next.servo_left >= -1 && out.next.servo_left <= 1 && out.next.servo_right >= -1 &&
                             out.next.servo_right <= 1);
    return {confirmed ? Verdict::refuted : Verdict::unknown,
            fmt::format("sat: drive_rule with {} commands servo_left = {}, servo_right = {} ({})", cc.text(),
                        out.next.servo_left, out.next.servo_right,
                        confirmed ? "confirmed by running drive_rule"
                                  : "NOT reproduced by the executed code: a spurious counterexample"),
            {}};
  }
  if (answer != z3::unsat) return {Verdict::unknown, "z3: unknown on drive-rule (" + reason + ")", {}};
  // controller_rule: every branch (idle, accepting, arrived, the maneuvers).
  const exploration::ControllerCoreT<S> next = handshake::traced_controller_rule(p, f.state, f.in);
  const auto m = out_of_range(session, next.servo_left, next.servo_right, "controller-rule", answer, reason);
  if (!m && answer == z3::unsat)
    return {Verdict::proved,
            "unsat: for every controller state and every input (doubles, NaN and infinities included) the "
            "commands drive_rule and controller_rule give are in [-1, 1]",
            {}};
  if (!m) return {Verdict::unknown, "z3: unknown on controller-rule (" + reason + ")", {}};
  // Replay through the executed controller: controller_step on the model's doubles.
  const ConcreteController cc = concrete_of(*m, t, f);
  const exploration::ControllerState out = exploration::controller_step(rp, cc.state, cc.in);
  const bool confirmed =
      !(out.servo_left >= -1 && out.servo_left <= 1 && out.servo_right >= -1 && out.servo_right <= 1);
  return {confirmed ? Verdict::refuted : Verdict::unknown,
          fmt::format("sat: controller_step with {} commands servo_left = {}, servo_right = {} ({})", cc.text(),
                      out.servo_left, out.servo_right,
                      confirmed ? "confirmed by running controller_step"
                                : "NOT reproduced by the executed code: a spurious counterexample"),
          {}};
}

}  // namespace

std::vector<Obligation> servo_obligations() {
  const std::vector<std::string> assumptions = {
      "v and w (the controller's linear and turn commands) are free IEEE doubles: any value the "
      "controller could compute, NaN and both infinities included",
      "the mix and the clamps are the spec's own definitions (servo_mix_rule, saturate_servo_rule, "
      "thesis_clamp_rule) interpreted over IEEE doubles: round to nearest even, no fused "
      "multiply-add, the RobotParams defaults",
  };
  return {
      Obligation{"servo-saturation",
                 "For every double v and w the spec's servo mix followed by saturate_servo gives "
                 "both servo commands in [-1, 1], never NaN.",
                 Verdict::proved, assumptions,
                 [](Session& s) {
                   return check_clamp(s, servo::Clamp::spec, exploration::saturate_servo,
                                      "saturate-servo");
                 },
                 {}},
      Obligation{"servo-thesis-clamp",
                 "The same property with the thesis's clamp (if (s > 1) s = 1; else if (s < -1) "
                 "s = -1;) in place of saturate_servo: refuted, NaN passes through.",
                 Verdict::refuted, assumptions,
                 [](Session& s) {
                   return check_clamp(s, servo::Clamp::thesis, exploration::thesis_clamp,
                                      "thesis-clamp");
                 },
                 {}},
      Obligation{"servo-controller-range",
                 "For every controller state and every input (pose, waypoint, handshake; any doubles, NaN and "
                 "infinities included) the servo commands the controller outputs, through controller_rule and "
                 "drive_rule, are in [-1, 1], never NaN; so after every master step, for every number of robots.",
                 Verdict::proved,
                 {"the whole of the spec's controller_rule and drive_rule (whatever they call: the arrival test, the "
                  "maneuvers, the atan2 fix, the bearing, the mix and the saturation) interpreted over IEEE doubles, "
                  "round to nearest even, the RobotParams defaults",
                  "first with every arithmetic operation abstracted to a free double (an over-approximation: the "
                  "saturation alone must keep the range); only if that has a model, exactly (bit-blasted), so that a "
                  "counterexample is a model of the code for the replay",
                  "atan2, the angle wrap's remainder, cos and sin are uninterpreted: any double (so any library's "
                  "results, NaN included)",
                  "every master step gives each robot's controller its own inputs (master_step's robots stage), so the "
                  "range holds for every number of robots",
                  "controller_step (the concrete packing of controller_rule's result into ControllerState) is not "
                  "interpreted: a counterexample is replayed through it"},
                 check_controller, [] { return handshake::servo_quantities(); }},
  };
}

}  // namespace swarmcheck::proofs
