// servo-saturation on concrete values: the spec's saturation and controller keep every servo
// command in [-1, 1] for any double, NaN and infinities included; the thesis's clamp does not;
// and the spec's rules interpreted in the FP theory compute the executed rules bit for bit.
#include <cstdlib>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "proofs/obligations/runner.hpp"
#include "proofs/obligations/servo.hpp"
#include "spec/exploration/controller.hpp"

namespace swarmcheck::proofs {
namespace {

// One seed for every run (an RC_PARAMS in the environment wins): CI and a developer see the
// same cases.
const bool kSeededProofsServoTest = [] { return ::setenv("RC_PARAMS", "seed=17", 0) == 0; }();

using exploration::RobotParams;

// Any double, with the special values often enough to matter.
rc::Gen<double> any_double() {
  constexpr double inf = std::numeric_limits<double>::infinity();
  return rc::gen::oneOf(
      rc::gen::arbitrary<double>(),
      rc::gen::map(rc::gen::arbitrary<uint64_t>(), [](uint64_t b) { return std::bit_cast<double>(b); }),
      rc::gen::element(std::nan(""), inf, -inf, 0.0, -0.0, 1.0, -1.0, std::nextafter(1.0, 2.0),
                       std::nextafter(-1.0, -2.0), std::numeric_limits<double>::max(),
                       std::numeric_limits<double>::denorm_min()));
}

bool in_unit_range(double s) { return s >= -1.0 && s <= 1.0; }   // false for NaN

// Evaluates a ground FP term to the double it denotes.
double eval_double(const z3::expr& e) {
  const z3::expr s = e.simplify();
  if (s.mk_is_nan().simplify().is_true()) return std::nan("");
  return std::bit_cast<double>(static_cast<uint64_t>(s.mk_to_ieee_bv().simplify().get_numeral_uint64()));
}

bool same_double(double a, double b) {
  return (std::isnan(a) && std::isnan(b)) || std::bit_cast<uint64_t>(a) == std::bit_cast<uint64_t>(b);
}

RC_GTEST_PROP(ServoProof, SaturateServoMapsEveryDoubleIntoTheUnitRange, ()) {
  const double u = *any_double();
  RC_ASSERT(in_unit_range(exploration::saturate_servo(u)));
}

RC_GTEST_PROP(ServoProof, ControllerServosStayInTheUnitRangeForAnyPoseAndWaypoint, ()) {
  const RobotParams rp;
  exploration::ControllerState s = exploration::initial_controller();
  s.on_destination_output = 0;
  s.maneuver = *rc::gen::element(1, 2);
  const exploration::ControllerInputs in{{*any_double(), *any_double(), *any_double()},
                                         {*any_double(), *any_double()},
                                         0,
                                         0.1};
  const exploration::ControllerState n = exploration::controller_step(rp, s, in);
  RC_ASSERT(in_unit_range(n.servo_left));
  RC_ASSERT(in_unit_range(n.servo_right));
}

// The two interpretations of one definition agree: the spec's mix and clamps, interpreted in
// Z3's FP theory and evaluated at v and w, give the bits the executed code computes.
RC_GTEST_PROP(ServoProof, SymbolicServoRulesInFpTheoryEqualTheExecutedRulesBitForBit, ()) {
  const RobotParams rp;
  const double v = *any_double(), w = *any_double();
  z3::context c;
  Translator t(c, RealTheory::fp64);
  const sym::Real sv = sym::Real::var("v"), sw = sym::Real::var("w");
  z3::expr_vector from(c), to(c);
  from.push_back(t(sv));
  from.push_back(t(sw));
  to.push_back(c.fpa_val(v));
  to.push_back(c.fpa_val(w));
  auto at = [&](const z3::expr& e) { return eval_double(z3::expr(e).substitute(from, to)); };
  const auto mix = exploration::servo_mix_rule<num::Concrete>(exploration::controller_params(rp), v, w);
  const servo::Commands spec = servo::commands(t, rp, sv, sw, servo::Clamp::spec);
  const servo::Commands thesis = servo::commands(t, rp, sv, sw, servo::Clamp::thesis);
  RC_ASSERT(same_double(at(spec.left), exploration::saturate_servo(mix.left)));
  RC_ASSERT(same_double(at(spec.right), exploration::saturate_servo(mix.right)));
  RC_ASSERT(same_double(at(thesis.left), exploration::thesis_clamp(mix.left)));
  RC_ASSERT(same_double(at(thesis.right), exploration::thesis_clamp(mix.right)));
}

TEST(ServoProof, TheThesisClampLetsNaNThroughOnConcreteValues) {
  EXPECT_TRUE(std::isnan(exploration::thesis_clamp(std::nan(""))));
  EXPECT_EQ(exploration::saturate_servo(std::nan("")), 0.0);
}

TEST(ServoProof, Z3ProvesTheSpecsSaturationAndRefutesTheThesisClampWithNaN) {
  const ObligationReport ok = run_in_process(*find_obligation("servo-saturation"), kQueryTimeoutMs);
  EXPECT_EQ(ok.result, Verdict::proved) << ok.detail;
  ASSERT_EQ(ok.queries.size(), 1U);
  EXPECT_EQ(ok.queries[0].answer, "unsat");
  const ObligationReport bad = run_in_process(*find_obligation("servo-thesis-clamp"), kQueryTimeoutMs);
  EXPECT_EQ(bad.result, Verdict::refuted) << bad.detail;
  ASSERT_EQ(bad.queries.size(), 1U);
  EXPECT_EQ(bad.queries[0].answer, "sat");
  EXPECT_NE(bad.detail.find("nan"), std::string::npos) << bad.detail;
  EXPECT_NE(bad.detail.find("confirmed by running the executed code"), std::string::npos);
}

}  // namespace
}  // namespace swarmcheck::proofs
