// The intocps body (spec/exploration/body_intocps.hpp) against thesis A's 20-sim Body_Block
// binary: seven 60 s input profiles with the binary's outputs at every 0.1 s step (measured data,
// copied from ../shared/fixtures/intocps-body/ into tests/exploration/fixtures/). The spec's step,
// the model's robot stage (spec/exploration/robot.hpp) and the library's batched bodies
// (impl/exploration/intocps_bodies.hpp) must each give every output, at every row, by bits.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "impl/exploration/intocps_bodies.hpp"
#include "spec/exploration/body_intocps.hpp"
#include "spec/exploration/robot.hpp"
#include "spec/exploration/scenario.hpp"
#include "tests/exploration/intocps_fixtures.hpp"

using namespace swarmcheck::exploration;
using namespace swarmcheck::testing;
namespace {

TEST(IntocpsBody, SevenFixtureProfilesAreThere) {
  const std::vector<Fixture> all = fixtures();
  ASSERT_EQ(all.size(), 7u);
  for (const Fixture& f : all) EXPECT_EQ(f.rows.size(), 601u) << f.name;
}

TEST(IntocpsBody, TheSpecStepGivesTheBinarysOutputsBitForBitAtEveryRowOfEveryProfile) {
  for (const Fixture& f : fixtures()) {
    const IntocpsBodyModel m = intocps_body_model(f.params);
    IntocpsBodyState s = intocps_body_initialised(0.0, f.params.initial_position[0], f.params.initial_position[1]);
    for (std::size_t k = 0; k < f.rows.size(); ++k) {
      if (k > 0) s = intocps_body_step(m, s, f.rows[k][2], f.rows[k][3], static_cast<double>(k - 1) * 0.1, 0.1);
      const std::string diff = compare(f, k, outputs_of(s.outputs));
      ASSERT_EQ(diff, "");
    }
  }
}

// The model runs a robot's body through robot.hpp (what ExplorationModel's robot stage calls),
// with the master's clock by repeated addition: the fixtures' t = k * 0.1 gives the same RK4
// counts here (checked by the bits).
TEST(IntocpsBody, TheModelsRobotStageGivesTheBinarysOutputsBitForBit) {
  for (const Fixture& f : fixtures()) {
    Scenario s = default_scenario();
    s.body.kind = BodyKind::intocps;
    s.body.intocps = f.params;
    const RobotConfig c = make_robot_config(s);
    BodyMemory b = initial_body(c, {f.params.initial_position[0], f.params.initial_position[1]});
    for (std::size_t k = 0; k < f.rows.size(); ++k) {
      if (k > 0) body_advance(c, b, f.rows[k][2], f.rows[k][3], static_cast<double>(k - 1) * 0.1);
      ASSERT_EQ(compare(f, k, outputs_of(b.intocps->outputs)), "");
      ASSERT_EQ(b.pose.x_m, b.intocps->outputs.robot_x);
    }
  }
}

// The library steps many bodies at once, in parallel: each fixture profile driven on 9 robots
// (odd, so the parallel ranges split unevenly), every robot equal to the binary.
TEST(IntocpsBody, TheLibrarysBatchedBodiesGiveTheBinarysOutputsBitForBitOnEveryRobot) {
  tbb::task_arena arena(2);
  for (const Fixture& f : fixtures()) {
    const std::size_t n = 9;
    const std::vector<Point_m> starts(n, Point_m{f.params.initial_position[0], f.params.initial_position[1]});
    swarmcheck::impl::exploration::IntocpsBodies bodies(intocps_body_model(f.params), starts);
    std::vector<double> left(n), right(n);
    for (std::size_t k = 0; k < f.rows.size(); ++k) {
      if (k > 0) {
        std::fill(left.begin(), left.end(), f.rows[k][2]);
        std::fill(right.begin(), right.end(), f.rows[k][3]);
        bodies.step(left, right, static_cast<double>(k - 1) * 0.1, 0.1, arena, k % 2 == 0);
      }
      for (std::size_t r = 0; r < n; ++r) ASSERT_EQ(compare(f, k, outputs_of(bodies.state(r).outputs)), "") << "robot " << r;
    }
  }
}

// Robots with different inputs in one batch: the four default-parameter profiles side by side.
TEST(IntocpsBody, DifferentInputsInOneBatchEachGiveTheirProfilesBits) {
  std::vector<Fixture> same;
  for (Fixture& f : fixtures())
    if (f.params == IntocpsBodyParams{}) same.push_back(std::move(f));
  ASSERT_EQ(same.size(), 4u);
  tbb::task_arena arena(2);
  const std::vector<Point_m> starts(same.size(), Point_m{0.138, -0.08});
  swarmcheck::impl::exploration::IntocpsBodies bodies(intocps_body_model(IntocpsBodyParams{}), starts);
  std::vector<double> left(same.size()), right(same.size());
  for (std::size_t k = 0; k < 601; ++k) {
    if (k > 0) {
      for (std::size_t r = 0; r < same.size(); ++r) {
        left[r] = same[r].rows[k][2];
        right[r] = same[r].rows[k][3];
      }
      bodies.step(left, right, static_cast<double>(k - 1) * 0.1, 0.1, arena, true);
    }
    for (std::size_t r = 0; r < same.size(); ++r) ASSERT_EQ(compare(same[r], k, outputs_of(bodies.state(r).outputs)), "");
  }
}

TEST(IntocpsBody, AStepOfHZeroDoesNothingAndACommunicationStepIs99To101SolverSteps) {
  const IntocpsBodyModel m = intocps_body_model(IntocpsBodyParams{});
  IntocpsBodyState s = intocps_body_initialised(0.0, 1.0, 2.0);
  EXPECT_EQ(intocps_body_do_step(m, s, 1.0, -1.0, 0.0, 0.0), 0);
  int32_t least = 1000, most = 0;
  for (int k = 0; k < 600; ++k) {
    const int32_t n = intocps_body_do_step(m, s, 0.5, -0.5, k * 0.1, 0.1);
    least = std::min(least, n);
    most = std::max(most, n);
  }
  EXPECT_GE(least, 99);
  EXPECT_LE(most, 101);
  EXPECT_LT(least, most);   // the clock by repeated addition lands on both sides of some points
}

TEST(IntocpsBody, RightAfterInitialisationThePositionReadsZeroAndTheHeadingTheDefault) {
  // The binary's memory: D is POS as of setup's F (zero in a fresh process), Theta the default theta0.
  const IntocpsBodyState s = intocps_body_initialised(0.0, 3.0, 4.0);
  EXPECT_EQ(s.outputs.robot_x, 0.0);
  EXPECT_EQ(s.outputs.robot_y, 0.0);
  EXPECT_EQ(s.outputs.robot_theta, 0.0);
}

TEST(IntocpsBody, TheLuInverseOfARotationIsItsTransposeWithinAnUlp) {
  for (const double theta : {0.0, 0.3, 1.0, 2.5, -2.0, 3.14159}) {
    const Mat2 r{{{std::cos(theta), -std::sin(theta)}, {std::sin(theta), std::cos(theta)}}};
    const Mat2 inv = intocps_lu_inverse(r);
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) EXPECT_NEAR(inv[i][j], r[j][i], 4e-16) << theta;
  }
}

}  // namespace
