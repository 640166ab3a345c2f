// Obligations orientation-held and orientation-held-thesis (SPEC.md section 8, "Arrival"): the
// mechanism of the stall on the 20-sim body. Turning in place, the body's reported point circles
// the axle (axle_offset = 1.85 cm ahead of it), so an orienting controller reads positions up to
// 2 a apart at one heading. If the bearing it turns towards depends on that position, two such
// readings can put the target on opposite sides of the heading, and the robot turns back and
// forth for ever (the old rule did at its deadband line, |dx| = tolerance).
//
// Property: in maneuver 1, near the waypoint (not arrived, |dx| + |dy| < 4 tolerances), at two
// positions at most 2 a apart and one heading theta, the bearing errors beta do not have opposite
// signs. Stated over the controller's whole step (controller_rule / thesis_controller_rule: the
// functions the executed controller_step calls), the pose and the target it holds free.
#include <cmath>
#include <numbers>
#include <fmt/format.h>

#include "proofs/obligations/obligation.hpp"
#include "proofs/obligations/translate.hpp"
#include "spec/exploration/body_intocps.hpp"
#include "spec/exploration/controller.hpp"
#include "spec/exploration/controller_thesis.hpp"

namespace swarmcheck::proofs {
namespace {

using S = num::Symbolic;
using C = num::Concrete;

z3::expr abs_value(const z3::expr& v) { return z3::ite(v < 0, -v, v); }

constexpr double kStep_s = 0.1;   // sets only the servos' gains, which the property does not read

// beta after one orienting step of the controller, at a position and heading.
template <class D>
typename D::Real beta_after(bool thesis, const typename D::Real& x, const typename D::Real& y,
                            const typename D::Real& theta, const typename D::Real& target) {
  using Real = typename D::Real;
  using Bool = typename D::Bool;
  const exploration::ControllerCoreT<D> busy_orienting{Bool(false), Bool(false), Real(0.0), Real(0.0), Real(0.0), target};
  const exploration::ControllerInputsT<D> in{x, y, theta, Real(0.0), Real(0.0), Bool(false), Real(kStep_s)};
  // num::traced marks the value with the function that computed it (symbolic interpretation
  // only): the reads check compares these with the executed step's calls.
  if (thesis) {
    const exploration::ThesisControllerParams tp;
    return num::traced("exploration::thesis_controller_rule",
                       exploration::thesis_controller_rule<D>(exploration::thesis_controller_params_t<D>(tp),
                                                              busy_orienting, in)
                           .beta_rad);
  }
  const exploration::RobotParams rp;
  const auto p = [&] {
    if constexpr (num::is_concrete<D>) return exploration::controller_params(rp);
    else return exploration::symbolic_controller_params(rp);
  }();
  return num::traced("exploration::controller_rule", exploration::controller_rule<D>(p, busy_orienting, in).beta_rad);
}

// The executed step's quantity: beta after controller_step's rule (controller_rule or
// thesis_controller_rule) on an orienting controller, every input free.
std::vector<sym::NodePtr> orienting_step(bool thesis) {
  return {beta_after<S>(thesis, sym::Real::var("x"), sym::Real::var("y"), sym::Real::var("theta"),
                        sym::Real::var("target"))
              .node()};
}

Outcome run_orientation(Session& session, bool thesis) {
  Translator t(session, RealTheory::real);
  z3::solver s = session.make_nonlinear_solver();
  const exploration::RobotParams rp;
  const exploration::ThesisControllerParams tp;
  const double tolerance = thesis ? tp.arrival_m : rp.tolerance_m;
  const double a = exploration::IntocpsBodyParams{}.axle_offset;
  // The waypoint at the origin: positions are relative to it (the rules read differences).
  const sym::Real x1 = sym::Real::var("x1"), y1 = sym::Real::var("y1"), x2 = sym::Real::var("x2"),
                  y2 = sym::Real::var("y2"), theta = sym::Real::var("theta"), target = sym::Real::var("target");
  const z3::expr zx1 = t(x1), zy1 = t(y1), zx2 = t(x2), zy2 = t(y2), zt = t(theta);
  const z3::expr tol = t(sym::Real(tolerance)), span = t(sym::Real(2 * a));
  for (const auto& [zx, zy] : {std::pair{zx1, zy1}, std::pair{zx2, zy2}}) {
    s.add(abs_value(zx) + abs_value(zy) >= tol);       // not arrived
    s.add(abs_value(zx) + abs_value(zy) < 4 * tol);    // in the arrival neighbourhood
  }
  s.add((zx1 - zx2) * (zx1 - zx2) + (zy1 - zy2) * (zy1 - zy2) <= span * span);
  s.add(zt >= t(sym::Real(-std::numbers::pi)) && zt <= t(sym::Real(std::numbers::pi)));
  const z3::expr b1 = t(beta_after<S>(thesis, x1, y1, theta, target));
  const z3::expr b2 = t(beta_after<S>(thesis, x2, y2, theta, target));
  s.add(t.side_conditions());
  s.add(b1 > 0 && b2 < 0);   // the negation: the target on opposite sides of the heading
  const char* label = thesis ? "thesis" : "swarmcheck";
  switch (session.check(s, label)) {
    case z3::unsat:
      return {Verdict::proved, "unsat: beta keeps its side of the heading wherever the reported point reads", {}};
    case z3::sat: {
      const z3::model m = s.get_model();
      const double px1 = model_double(m, zx1), py1 = model_double(m, zy1), px2 = model_double(m, zx2),
                   py2 = model_double(m, zy2), th = model_double(m, zt), tg = model_double(m, t(target));
      // Replay through the executed code: the concrete instantiation of the same rule. atan2 is
      // uninterpreted in the query, so the solver's heading may not reproduce; the two positions
      // are then tried at 720 headings over [-pi, pi] (the property is for every heading, so any
      // one that reproduces is a counterexample), each checked by running the step.
      const auto reproduces = [&](double heading) {
        const double c1 = beta_after<C>(thesis, px1, py1, heading, tg), c2 = beta_after<C>(thesis, px2, py2, heading, tg);
        return c1 > 0 && c2 < 0;
      };
      const bool near = std::hypot(px1 - px2, py1 - py2) <= 2 * a;
      double heading = th;
      bool confirmed = near && reproduces(heading);
      const bool at_solver_heading = confirmed;
      for (int k = 0; near && !confirmed && k <= 720; ++k) {
        heading = -std::numbers::pi + k * (2 * std::numbers::pi / 720);
        confirmed = reproduces(heading);
      }
      const double c1 = beta_after<C>(thesis, px1, py1, heading, tg), c2 = beta_after<C>(thesis, px2, py2, heading, tg);
      return {confirmed ? Verdict::refuted : Verdict::unknown,
              fmt::format("sat: at heading {:.6f}, positions ({:.6g}, {:.6g}) and ({:.6g}, {:.6g}) relative to the "
                          "waypoint ({:.4g} m apart) give beta {:.6f} and {:.6f} ({})",
                          heading, px1, py1, px2, py2, std::hypot(px1 - px2, py1 - py2), c1, c2,
                          !confirmed ? "NOT reproduced by the executed code at any of 720 headings: a spurious counterexample"
                          : at_solver_heading ? "confirmed by running the controller's step"
                                              : fmt::format("confirmed by running the controller's step; the solver's "
                                                            "heading {:.6f} did not reproduce", th)),
              {}};
    }
    default:
      return {Verdict::unknown, "z3: unknown (" + s.reason_unknown() + ")", {}};
  }
}

}  // namespace

std::vector<Obligation> orientation_obligations() {
  const std::vector<std::string> assumptions = {
      "relative coordinates: the waypoint at the origin; two positions at most 2 axle_offset (3.7 cm) apart "
      "(the reported point circling the axle as the robot turns in place), each not arrived and within 4 "
      "tolerances of the waypoint (|dx| + |dy|); one heading in [-pi, pi]; the target held free",
      "the controller's whole step on a busy, orienting state (maneuver 1), its symbolic interpretation; "
      "nonlinear real arithmetic, qfnra-nlsat",
      "atan2 and the wrap's remainder uninterpreted with their ranges and quadrant facts; reals, not doubles: "
      "a counterexample counts only when the doubles nearest its values reproduce it through the executed step",
  };
  return {
      Obligation{"orientation-held",
                 "The default controller, orienting near its waypoint, turns the same way at any two positions "
                 "the reported point takes while the robot turns in place: beta never has opposite signs at one "
                 "heading (so the 20-sim body cannot make it chatter).",
                 Verdict::proved, assumptions, [](Session& s) { return run_orientation(s, false); },
                 [] { return orienting_step(false); }},
      Obligation{"orientation-held-thesis",
                 "The same for the thesis's published controller: refuted, its atan2 fix moves the bearing by "
                 "tens of degrees when a delta crosses the deadband line (0.2 m) within a few centimetres.",
                 Verdict::refuted, assumptions, [](Session& s) { return run_orientation(s, true); },
                 [] { return orienting_step(true); }},
  };
}

}  // namespace swarmcheck::proofs
