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
#include "spec/exploration/controller.hpp"

namespace swarmcheck::proofs {
namespace {

struct Atan2Term {   // one application atan2(y, x), Ackermannized to the real `value`
  z3::expr y, x, value;
};

// Sign and quadrant facts of atan2 for one application, as ground formulas (no quantifiers:
// VERIFICATION.md, forall axioms make satisfiable queries come back unknown).
z3::expr atan2_axioms(const Atan2Term& a, const z3::expr& pi) {
  const z3::expr& b = a.value;
  const z3::expr half = pi / 2;
  return -pi < b && b <= pi && z3::implies(a.y == 0 && a.x > 0, b == 0) &&
         z3::implies(a.y == 0 && a.x < 0, b == pi) && z3::implies(a.y > 0 && a.x == 0, b == half) &&
         z3::implies(a.y < 0 && a.x == 0, b == -half) &&
         z3::implies(a.y > 0 && a.x > 0, 0 < b && b < half) &&
         z3::implies(a.y > 0 && a.x < 0, half < b && b < pi) &&
         z3::implies(a.y < 0 && a.x > 0, -half < b && b < 0) &&
         z3::implies(a.y < 0 && a.x < 0, -pi < b && b < -half);
}

z3::expr magnitude(const z3::expr& v) { return z3::ite(v < 0, -v, v); }

double to_double_approx(const z3::expr& e) { return std::stod(e.get_decimal_string(17)); }

Outcome run(Session& session, bool fix) {
  z3::context& c = session.ctx();
  const exploration::RobotParams rp;
  // 0.05 m exactly as a rational (the double 0.05 differs from 1/20 in the 18th digit).
  const z3::expr tol = c.real_val(1, 20);
  const z3::expr pi = c.real_const("pi");
  z3::solver s = session.make_nonlinear_solver();
  s.add(c.real_val("3.14159") < pi && pi < c.real_val("3.1416"));
  const z3::expr dx1 = c.real_const("dx1"), dy1 = c.real_const("dy1");
  const z3::expr dx2 = c.real_const("dx2"), dy2 = c.real_const("dy2");
  // Two positions closer than the tolerance, in the same strip, neither arrived.
  s.add((dx1 - dx2) * (dx1 - dx2) + (dy1 - dy2) * (dy1 - dy2) < tol * tol);
  const z3::expr y_strip = magnitude(dy1) < tol && magnitude(dx1) >= tol && magnitude(dy2) < tol && magnitude(dx2) >= tol;
  const z3::expr x_strip = magnitude(dx1) < tol && magnitude(dy1) >= tol && magnitude(dx2) < tol && magnitude(dy2) >= tol;
  s.add(y_strip || x_strip);
  // The deltas maneuver 1 gives atan2: with the fix, a delta below the tolerance is 0 unless
  // both are.
  auto fixed = [&](const z3::expr& d, const z3::expr& other) {
    if (!fix) return d;
    return z3::ite(magnitude(d) < tol && magnitude(other) < tol, d, z3::ite(magnitude(d) < tol, c.real_val(0), d));
  };
  const Atan2Term b1{fixed(dy1, dx1), fixed(dx1, dy1), c.real_const("atan2_1")};
  const Atan2Term b2{fixed(dy2, dx2), fixed(dx2, dy2), c.real_const("atan2_2")};
  s.add(atan2_axioms(b1, pi) && atan2_axioms(b2, pi));
  s.add(z3::implies(b1.y == b2.y && b1.x == b2.x, b1.value == b2.value));   // atan2 is a function
  s.add(!(magnitude(b1.value - b2.value) < pi));
  switch (session.check(s, fix ? "with-fix" : "without-fix")) {
    case z3::unsat:
      return {Verdict::proved, "unsat: the bearing cannot jump by pi or more within the strip", {}};
    case z3::sat: {
      const z3::model m = s.get_model();
      auto val = [&](const z3::expr& e) {
        const z3::expr v = m.eval(e, true);
        return v.is_numeral() ? to_double_approx(v) : std::nan("");
      };
      const double x1 = val(dx1), y1 = val(dy1), x2 = val(dx2), y2 = val(dy2);
      const double a1 = std::atan2(y1, x1), a2 = std::atan2(y2, x2);
      // Beta at both positions through the spec's controller (maneuver 1, heading theta = 0).
      auto beta = [&](double dx, double dy) {
        exploration::ControllerState st = exploration::initial_controller();
        st.on_destination_output = 0;
        const exploration::ControllerInputs in{{0.0, 0.0, 0.0}, {dx, dy}, 0};
        return exploration::controller_step(rp, st, in).beta_rad;
      };
      return {Verdict::refuted,
              fmt::format("sat: deltas ({:.6g}, {:.6g}) and ({:.6g}, {:.6g}): atan2 = {:.6f} and "
                          "{:.6f} ({}); the spec's fixed controller gives beta = {:.6f} at both: {:.6f}",
                          x1, y1, x2, y2, a1, a2,
                          std::fabs(a1 - a2) >= M_PI ? "confirmed with std::atan2" : "NOT reproduced by std::atan2",
                          beta(x1, y1), beta(x2, y2)),
              {}};
    }
    default:
      return {Verdict::unknown, "z3: unknown (" + s.reason_unknown() + ")", {}};
  }
}

}  // namespace

std::vector<Obligation> atan2_obligations() {
  const std::vector<std::string> assumptions = {
      "relative coordinates: dx, dy = waypoint - position at two positions less than the "
      "tolerance (0.05 m) apart, both in one deadband strip (|dy| < tol <= |dx|, or x and y "
      "exchanged); nonlinear real arithmetic, qfnra-nlsat",
      "atan2 is uninterpreted, Ackermannized: one real per application with its range (-pi, pi] "
      "and sign / quadrant facts as ground formulas, plus functional consistency",
      "pi is a real between 3.14159 and 3.1416; reals, not doubles",
  };
  return {
      Obligation{"atan2-fix",
                 "In maneuver 1, at two positions closer than the tolerance in one deadband strip "
                 "around the waypoint, the fixed bearing atan2(dy', dx') differs by less than pi "
                 "(it never flips across the +-pi cut, so beta cannot flip sign).",
                 Verdict::proved, assumptions, [](Session& s) { return run(s, true); }},
      Obligation{"atan2-without-fix",
                 "The same property for the raw deltas (no fix): refuted, the bearing flips from "
                 "about +pi to -pi when the waypoint is behind the robot on its axis.",
                 Verdict::refuted, assumptions, [](Session& s) { return run(s, false); }},
  };
}

}  // namespace swarmcheck::proofs
