// servo-saturation on concrete values: the spec's saturation and controller keep every servo
// command in [-1, 1] for any double, NaN and infinities included; the thesis's clamp does not;
// and the FP encoding of the proof computes the spec's functions bit for bit.
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
                                         0};
  const exploration::ControllerState n = exploration::controller_step(rp, s, in);
  RC_ASSERT(in_unit_range(n.servo_left));
  RC_ASSERT(in_unit_range(n.servo_right));
}

RC_GTEST_PROP(ServoProof, FpEncodingComputesTheSpecsMixAndSaturationBitForBit, ()) {
  const RobotParams rp;
  const double v = *any_double(), w = *any_double();
  z3::context c;
  const servo::Mix m = servo::mix(rp, c.fpa_val(v), c.fpa_val(w));
  const double r = rp.wheel_radius_m, l = 2 * rp.half_axle_m;
  const double left = (1 / r) * v + (l / (2 * r)) * w;
  const double right = -((1 / r) * v - (l / (2 * r)) * w);
  RC_ASSERT(same_double(eval_double(m.left), left));
  RC_ASSERT(same_double(eval_double(m.right), right));
  RC_ASSERT(same_double(eval_double(servo::saturate(m.left)), exploration::saturate_servo(left)));
  RC_ASSERT(same_double(eval_double(servo::thesis_clamp(m.left)), exploration::thesis_clamp(left)));
}

TEST(ServoProof, TheThesisClampLetsNaNThroughOnConcreteValues) {
  EXPECT_TRUE(std::isnan(exploration::thesis_clamp(std::nan(""))));
  EXPECT_EQ(exploration::saturate_servo(std::nan("")), 0.0);
}

TEST(ServoProof, Z3ProvesTheSpecsSaturationAndRefutesTheThesisClampWithNaN) {
  const ObligationReport ok = run_in_process(*find_obligation("servo-saturation"), 20000);
  EXPECT_EQ(ok.result, Verdict::proved) << ok.detail;
  ASSERT_EQ(ok.queries.size(), 1U);
  EXPECT_EQ(ok.queries[0].answer, "unsat");
  const ObligationReport bad = run_in_process(*find_obligation("servo-thesis-clamp"), 20000);
  EXPECT_EQ(bad.result, Verdict::refuted) << bad.detail;
  ASSERT_EQ(bad.queries.size(), 1U);
  EXPECT_EQ(bad.queries[0].answer, "sat");
  EXPECT_NE(bad.detail.find("nan"), std::string::npos) << bad.detail;
  EXPECT_NE(bad.detail.find("confirmed by running the spec's function"), std::string::npos);
}

}  // namespace
}  // namespace swarmcheck::proofs
