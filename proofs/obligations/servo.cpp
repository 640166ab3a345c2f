// Obligations servo-saturation (the spec's saturation) and servo-thesis-clamp (the thesis's).
#include "proofs/obligations/servo.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <fmt/format.h>

#include "proofs/obligations/obligation.hpp"
#include "spec/exploration/controller.hpp"

namespace swarmcheck::proofs {
namespace servo {

z3::expr saturate(const z3::expr& u) {
  z3::context& c = u.ctx();
  const z3::expr one = c.fpa_val(1.0), minus_one = c.fpa_val(-1.0), zero = c.fpa_val(0.0);
  return z3::ite(u.mk_is_nan(), zero, z3::ite(u > one, one, z3::ite(u < minus_one, minus_one, u)));
}

z3::expr thesis_clamp(const z3::expr& u) {
  z3::context& c = u.ctx();
  const z3::expr one = c.fpa_val(1.0), minus_one = c.fpa_val(-1.0);
  return z3::ite(u > one, one, z3::ite(u < minus_one, minus_one, u));
}

Mix mix(const exploration::RobotParams& rp, const z3::expr& v, const z3::expr& w) {
  z3::context& c = v.ctx();
  const double r = rp.wheel_radius_m;
  const double l = 2 * rp.half_axle_m;
  const z3::expr inv_r = c.fpa_val(1 / r);
  const z3::expr half_l_over_r = c.fpa_val(l / (2 * r));
  // operator+ / operator* on FP terms use the context's rounding mode, RNE by default.
  return Mix{inv_r * v + half_l_over_r * w, -(inv_r * v - half_l_over_r * w)};
}

}  // namespace servo

namespace {

// The double a model assigns to an FP constant (NaN has no unique IEEE encoding in SMT-LIB).
double model_double(const z3::model& m, const z3::expr& x) {
  if (m.eval(x.mk_is_nan(), true).is_true()) return std::nan("");
  const z3::expr bits = m.eval(x.mk_to_ieee_bv(), true);
  return std::bit_cast<double>(static_cast<uint64_t>(bits.get_numeral_uint64()));
}

using Clamp = z3::expr (*)(const z3::expr&);
using ConcreteClamp = double (*)(double);

// Is there a double v (linear command) and w (turn command), NaN and infinities included,
// for which a clamped servo command is NaN or outside [-1, 1]?
Outcome check_clamp(Session& session, Clamp clamp, ConcreteClamp concrete, const char* label) {
  z3::context& c = session.ctx();
  const exploration::RobotParams rp;
  const z3::expr v = c.fpa_const<64>("v"), w = c.fpa_const<64>("w");
  const servo::Mix m = servo::mix(rp, v, w);
  auto in_range = [&](const z3::expr& s) {
    return !s.mk_is_nan() && s >= c.fpa_val(-1.0) && s <= c.fpa_val(1.0);
  };
  z3::solver s = session.make_solver();
  s.add(!(in_range(clamp(m.left)) && in_range(clamp(m.right))));
  switch (session.check(s, label)) {
    case z3::unsat:
      return {Verdict::proved, "unsat: no double v, w (NaN and infinities included) gives a "
                               "servo command outside [-1, 1]", {}};
    case z3::sat: {
      const z3::model model = s.get_model();
      const double vv = model_double(model, v), ww = model_double(model, w);
      // Replay the counterexample through the spec's own functions.
      const double r = rp.wheel_radius_m, l = 2 * rp.half_axle_m;
      const double left = concrete((1 / r) * vv + (l / (2 * r)) * ww);
      const double right = concrete(-((1 / r) * vv - (l / (2 * r)) * ww));
      const bool confirmed = !(left >= -1 && left <= 1 && right >= -1 && right <= 1);
      return {Verdict::refuted,
              fmt::format("sat: v = {}, w = {} gives servo_left = {}, servo_right = {} ({})", vv,
                          ww, left, right,
                          confirmed ? "confirmed by running the spec's function"
                                    : "NOT reproduced by the spec's function"),
              {}};
    }
    default:
      return {Verdict::unknown, "z3: unknown (" + s.reason_unknown() + ")", {}};
  }
}

}  // namespace

std::vector<Obligation> servo_obligations() {
  const std::vector<std::string> assumptions = {
      "v and w (the controller's linear and turn commands) are free IEEE doubles: any value the "
      "controller could compute, NaN and both infinities included",
      "the mix is the spec's: (1/r) v + (L/(2r)) w and -((1/r) v - (L/(2r)) w) with 1/r and "
      "L/(2r) the doubles the spec computes, rounded to nearest even, no fused multiply-add",
  };
  return {
      Obligation{"servo-saturation",
                 "For every double v and w the spec's servo mix followed by saturate_servo gives "
                 "both servo commands in [-1, 1], never NaN.",
                 Verdict::proved, assumptions,
                 [](Session& s) {
                   return check_clamp(s, servo::saturate, exploration::saturate_servo,
                                      "saturate-servo");
                 }},
      Obligation{"servo-thesis-clamp",
                 "The same property with the thesis's clamp (if (s > 1) s = 1; else if (s < -1) "
                 "s = -1;) in place of saturate_servo: refuted, NaN passes through.",
                 Verdict::refuted, assumptions,
                 [](Session& s) {
                   return check_clamp(s, servo::thesis_clamp, exploration::thesis_clamp,
                                      "thesis-clamp");
                 }},
  };
}

}  // namespace swarmcheck::proofs
