// atan2-fix on concrete runs: two positions closer than the tolerance in one deadband strip
// give the spec's controller the same beta in maneuver 1; the raw atan2 flips at the +-pi cut.
#include <cstdlib>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "proofs/obligations/runner.hpp"
#include "spec/exploration/controller.hpp"

namespace swarmcheck::proofs {
namespace {

// One seed for every run (an RC_PARAMS in the environment wins): CI and a developer see the
// same cases.
const bool kSeededProofsAtan2Test = [] { return ::setenv("RC_PARAMS", "seed=17", 0) == 0; }();

double beta_at(double x, double y, double theta) {
  exploration::ControllerState s = exploration::initial_controller();
  s.on_destination_output = 0;   // busy, maneuver 1
  const exploration::ControllerInputs in{{x, y, theta}, {0.5, 0.5}, 0, 0.1};
  return exploration::controller_step(exploration::RobotParams{}, s, in).beta_rad;
}

RC_GTEST_PROP(Atan2Proof, NearbyPositionsInOneDeadbandStripGiveTheSameBeta, ()) {
  // Deltas (waypoint - position) in millimetres, kept off the strip's edges by 1 mm.
  const bool y_strip = *rc::gen::arbitrary<bool>();
  const double along = (*rc::gen::element(-1.0, 1.0)) * *rc::gen::inRange(70, 3000) / 1000.0;
  const int across_mm = *rc::gen::inRange(-48, 49);
  const double across = across_mm / 1000.0;
  const double d_along = *rc::gen::inRange(-9, 10) / 1000.0;
  const double across2 = *rc::gen::inRange(std::max(-48, across_mm - 30), std::min(48, across_mm + 30) + 1) / 1000.0;
  RC_ASSERT(std::hypot(d_along, across2 - across) < 0.05);
  const double theta = *rc::gen::inRange(-314, 315) / 100.0;
  auto position = [&](double a, double c) {
    const double dx = y_strip ? a : c, dy = y_strip ? c : a;
    return std::pair{0.5 - dx, 0.5 - dy};
  };
  const auto [x1, y1] = position(along, across);
  const auto [x2, y2] = position(along + d_along, across2);
  RC_ASSERT(beta_at(x1, y1, theta) == beta_at(x2, y2, theta));
}

TEST(Atan2Proof, WithoutTheFixTheBearingFlipsAcrossTheCutBehindTheRobot) {
  EXPECT_GT(std::atan2(0.01, -1.0) - std::atan2(-0.01, -1.0), std::numbers::pi);
  // With the fix the controller sees dy = 0 at both positions: one bearing, one beta.
  EXPECT_EQ(beta_at(1.5, 0.49, 0.3), beta_at(1.5, 0.51, 0.3));
}

TEST(Atan2Proof, Z3ProvesTheFixAndRefutesTheRawBearingConfirmedWithStdAtan2) {
  const ObligationReport ok = run_in_process(*find_obligation("atan2-fix"), kQueryTimeoutMs);
  EXPECT_EQ(ok.result, Verdict::proved) << ok.detail;
  const ObligationReport bad = run_in_process(*find_obligation("atan2-without-fix"), kQueryTimeoutMs);
  EXPECT_EQ(bad.result, Verdict::refuted) << bad.detail;
  EXPECT_NE(bad.detail.find("confirmed by running atan2_fix_rule"), std::string::npos) << bad.detail;
}

}  // namespace
}  // namespace swarmcheck::proofs
