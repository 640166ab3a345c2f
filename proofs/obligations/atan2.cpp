// Obligations atan2-fix and atan2-without-fix (SPEC.md section 8, maneuver 1).
//
// In relative coordinates (dx, dy) = waypoint - position, at two positions p1, p2 closer than
// the tolerance to each other, both in the same deadband strip (|dy| < tol <= |dx|, or the same
// with x and y exchanged): the bearing atan2(dy', dx') of the fixed deltas jumps by less than
// pi between them, so it never crosses the +-pi cut and beta = wrap(bearing - psi) keeps its
// turning direction for a heading. Without the fix the bearing flips between about +pi and -pi
// when the waypoint is behind the robot on its axis.
#include <cmath>
#include <fmt/format.h>

#include "proofs/obligations/obligation.hpp"
#include "proofs/obligations/translate.hpp"
#include "spec/exploration/controller.hpp"

namespace swarmcheck::proofs {
namespace {

using S = num::Symbolic;
using C = num::Concrete;

z3::expr magnitude(const z3::expr& v) { return z3::ite(v < 0, -v, v); }

// The bearing atan2(dy', dx') of maneuver 1 at a relative position, with the spec's fix or
// without it (the raw deltas).
template <class D>
typename D::Real bearing(const exploration::DeltaT<D>& d, const typename D::Real& tol, bool fix) {
  if (!fix) return num::atan2(d.dy, d.dx);
  const exploration::DeltaT<D> f = exploration::atan2_fix_rule<D>(d, tol);
  constexpr const char* fn = "exploration::atan2_fix_rule";
  return num::atan2(num::traced(fn, f.dy), num::traced(fn, f.dx));
}

// How many spurious counterexamples are blocked and asked again before the verdict is unknown.
constexpr int kChaseBudget = 8;

Outcome run_atan2(Session& session, bool fix) {
  const exploration::RobotParams rp;
  Translator t(session, RealTheory::real);
  z3::solver s = session.make_nonlinear_solver();
  const sym::Real tol_s(rp.tolerance_m);
  const exploration::DeltaT<S> p1{sym::Real::var("dx1"), sym::Real::var("dy1")};
  const exploration::DeltaT<S> p2{sym::Real::var("dx2"), sym::Real::var("dy2")};
  const z3::expr tol = t(tol_s), dx1 = t(p1.dx), dy1 = t(p1.dy), dx2 = t(p2.dx), dy2 = t(p2.dy);
  // The premise, stated here: two positions closer than the tolerance, in the same strip.
  s.add((dx1 - dx2) * (dx1 - dx2) + (dy1 - dy2) * (dy1 - dy2) < tol * tol);
  const z3::expr y_strip = magnitude(dy1) < tol && magnitude(dx1) >= tol && magnitude(dy2) < tol && magnitude(dx2) >= tol;
  const z3::expr x_strip = magnitude(dx1) < tol && magnitude(dy1) >= tol && magnitude(dx2) < tol && magnitude(dy2) >= tol;
  s.add(y_strip || x_strip);
  const z3::expr b1 = t(bearing<S>(p1, tol_s, fix)), b2 = t(bearing<S>(p2, tol_s, fix));
  s.add(t.side_conditions());
  // The property: the bearings differ by less than pi (the double nearest pi).
  s.add(!(magnitude(b1 - b2) < t(sym::Real(M_PI))));
  // A model that the executed code does not reproduce (its uninterpreted atan2 values are not
  // what std::atan2 gives at the nearest doubles) is blocked and Z3 asked again.
  std::string blocked;
  for (int round = 0; round <= kChaseBudget; ++round) {
    const std::string label = fmt::format("{}{}", fix ? "with-fix" : "without-fix", round == 0 ? "" : fmt::format("-{}", round));
    switch (session.check(s, label)) {
      case z3::unsat:
        return {Verdict::proved,
                "unsat: the bearing cannot jump by pi or more within the strip" +
                    (blocked.empty() ? std::string() : " (after blocking spurious models:" + blocked + ")"),
                {}};
      case z3::sat: {
        const z3::model m = s.get_model();
        const double x1 = model_double(m, dx1), y1 = model_double(m, dy1), x2 = model_double(m, dx2),
                     y2 = model_double(m, dy2);
        // Replay through the executed code: the concrete instantiation of the same rule.
        const double a1 = bearing<C>({x1, y1}, rp.tolerance_m, fix), a2 = bearing<C>({x2, y2}, rp.tolerance_m, fix);
        if (std::fabs(a1 - a2) >= M_PI)
          return {Verdict::refuted,
                  fmt::format("sat: deltas ({:.6g}, {:.6g}) and ({:.6g}, {:.6g}) give bearings {:.6f} and {:.6f} "
                              "(confirmed by running atan2_fix_rule and std::atan2{})",
                              x1, y1, x2, y2, a1, a2,
                              blocked.empty() ? "" : "; spurious models blocked first:" + blocked),
                  {}};
        // Spurious: block this model's deltas (exactly its values) and ask again.
        blocked += fmt::format(" ({:.3g}, {:.3g}) / ({:.3g}, {:.3g})", x1, y1, x2, y2);
        s.add(!(dx1 == m.eval(dx1, true) && dy1 == m.eval(dy1, true) && dx2 == m.eval(dx2, true) &&
                dy2 == m.eval(dy2, true)));
        break;
      }
      default:
        return {Verdict::unknown, "z3: unknown (" + s.reason_unknown() + ")", {}};
    }
  }
  return {Verdict::unknown,
          fmt::format("{} spurious counterexamples in a row (NOT reproduced by the executed code), the chase's budget:{}",
                      kChaseBudget + 1, blocked),
          {}};
}

}  // namespace

std::vector<Obligation> atan2_obligations() {
  const std::vector<std::string> assumptions = {
      "relative coordinates: dx, dy = waypoint - position at two positions less than the "
      "tolerance (0.05 m) apart, both in one deadband strip (|dy| < tol <= |dx|, or x and y "
      "exchanged); nonlinear real arithmetic, qfnra-nlsat",
      "the fix is the spec's atan2_fix_rule (its symbolic interpretation), the tolerance the "
      "RobotParams default as the exact value of its double",
      "atan2 is uninterpreted, Ackermannized: one real per application with its range [-pi_d, "
      "pi_d] (pi_d the double nearest pi) and sign / quadrant facts, plus functional consistency",
      "reals, not doubles: a counterexample counts only when the doubles nearest its values "
      "reproduce it through the executed code; a model they do not reproduce is blocked (its exact "
      "deltas excluded) and Z3 asked again, up to 8 times, before the verdict is unknown",
  };
  return {
      Obligation{"atan2-fix",
                 "In maneuver 1, at two positions closer than the tolerance in one deadband strip "
                 "around the waypoint, the fixed bearing atan2(dy', dx') differs by less than pi "
                 "(it never flips across the +-pi cut, so beta cannot flip sign).",
                 Verdict::proved, assumptions, [](Session& s) { return run_atan2(s, true); }, {}},
      Obligation{"atan2-without-fix",
                 "The same property for the raw deltas (no fix): refuted, the bearing flips from "
                 "about +pi to -pi when the waypoint is behind the robot on its axis.",
                 Verdict::refuted, assumptions, [](Session& s) { return run_atan2(s, false); }, {}},
  };
}

}  // namespace swarmcheck::proofs
