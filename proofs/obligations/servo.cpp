// Obligations servo-saturation (the spec's saturation) and servo-thesis-clamp (the thesis's).
#include "proofs/obligations/servo.hpp"

#include <cmath>
#include <cstdint>
#include <fmt/format.h>

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
  return Commands{t(sat(mix.left)), t(sat(mix.right))};
}

}  // namespace servo

namespace {

using ConcreteClamp = double (*)(double);

// Is there a double v (linear command) and w (turn command), NaN and infinities included,
// for which a clamped servo command is NaN or outside [-1, 1]?
Outcome check_clamp(Session& session, servo::Clamp clamp, ConcreteClamp concrete, const char* label) {
  z3::context& c = session.ctx();
  const exploration::RobotParams rp;
  Translator t(c, RealTheory::fp64);
  const sym::Real sv = sym::Real::var("v"), sw = sym::Real::var("w");
  const z3::expr v = t(sv), w = t(sw);
  const servo::Commands m = servo::commands(t, rp, sv, sw, clamp);
  // The property, stated here: both commands are numbers in [-1, 1].
  auto in_range = [&](const z3::expr& s) {
    return !s.mk_is_nan() && s >= c.fpa_val(-1.0) && s <= c.fpa_val(1.0);
  };
  z3::solver s = session.make_solver();
  s.add(t.side_conditions());
  s.add(!(in_range(m.left) && in_range(m.right)));
  switch (session.check(s, label)) {
    case z3::unsat:
      return {Verdict::proved, "unsat: no double v, w (NaN and infinities included) gives a "
                               "servo command outside [-1, 1]", {}};
    case z3::sat: {
      const z3::model model = s.get_model();
      const double vv = model_double(model, v), ww = model_double(model, w);
      // Replay the counterexample through the executed code: the concrete instantiation.
      const auto mix = exploration::servo_mix_rule<num::Concrete>(exploration::controller_params(rp), vv, ww);
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
                 {"exploration::servo_mix_rule", "exploration::saturate_servo_rule"}},
      Obligation{"servo-thesis-clamp",
                 "The same property with the thesis's clamp (if (s > 1) s = 1; else if (s < -1) "
                 "s = -1;) in place of saturate_servo: refuted, NaN passes through.",
                 Verdict::refuted, assumptions,
                 [](Session& s) {
                   return check_clamp(s, servo::Clamp::thesis, exploration::thesis_clamp,
                                      "thesis-clamp");
                 },
                 {"exploration::servo_mix_rule", "exploration::thesis_clamp_rule"}},
  };
}

}  // namespace swarmcheck::proofs
