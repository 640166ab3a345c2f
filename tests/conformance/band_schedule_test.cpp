// The band schedule (impl/exploration/band_schedule.hpp) runs robots that may touch a cell in
// common in index order, whatever the threads: checked on the schedule itself, by the order in
// which it calls the work, on generated layouts. (threads_test.cpp checks the simulation's bits.)
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <numeric>
#include <vector>

#include "impl/exploration/band_schedule.hpp"
#include "spec/exploration/rng.hpp"
#include "tests/conformance/schedule_order.hpp"

using swarmcheck::exploration::CellIndex;
using swarmcheck::impl::exploration::BandSchedule;

using swarmcheck::testing::run_order;

namespace {

const bool kSeededBandScheduleTest = [] { return ::setenv("RC_PARAMS", "seed=17", 0) == 0; }();

bool conflict(const CellIndex& a, const CellIndex& b, int32_t reach) {
  return std::abs(a[0] - b[0]) <= reach && std::abs(a[1] - b[1]) <= reach;
}

}  // namespace

RC_GTEST_PROP(BandSchedule, EveryRobotRunsOnceAndConflictingRobotsRunInIndexOrderOnAnySparseLayout, ()) {
  const int32_t map = *rc::gen::inRange(8, 200);
  const int32_t reach = *rc::gen::inRange(1, 7);
  const int32_t strips = *rc::gen::inRange(2, 9);
  const int64_t cells = int64_t{map} * map;
  // Up to the density where build() still accepts, and a little beyond (where it declines).
  const auto max_robots = static_cast<int32_t>(std::max<int64_t>(2, cells * 3 / ((2 * reach + 1) * (2 * reach + 1) * 2)));
  const int32_t robots = *rc::gen::inRange(2, max_robots + 1);
  const auto seed = *rc::gen::arbitrary<uint64_t>();
  std::vector<CellIndex> at(static_cast<std::size_t>(robots));
  for (std::size_t r = 0; r < at.size(); ++r) {   // cells may repeat (deposit centres can)
    const uint64_t c = swarmcheck::exploration::splitmix64(seed + r) % static_cast<uint64_t>(cells);
    at[r] = CellIndex{static_cast<int32_t>(c / map), static_cast<int32_t>(c % map)};
  }
  BandSchedule b;
  if (!b.build(at, map, reach, strips)) RC_DISCARD("too dense, or one strip");
  RC_TAG(b.deferred().empty() ? "none deferred" : "some deferred");
  tbb::task_arena arena(*rc::gen::element(1, 2, 4));
  const std::vector<int64_t> order = run_order(b, arena, at.size());
  for (std::size_t r = 0; r < at.size(); ++r) RC_ASSERT(order[r] >= 0);
  for (std::size_t a = 0; a < at.size(); ++a)
    for (std::size_t c = a + 1; c < at.size(); ++c)
      if (conflict(at[a], at[c], reach)) RC_ASSERT(order[a] < order[c]);
}

TEST(BandSchedule, DefersTheBorderRobotsAndTheChainsOfLargerIndexThatLeadAwayFromThem) {
  // A 40^2 map, reach 2, two strips cut at row 20 (9 robots below, 9 above).
  std::vector<CellIndex> at(18);
  for (int32_t k = 0; k < 5; ++k) at[static_cast<std::size_t>(4 + k)] = CellIndex{2 * k, 30};   // far from the edge
  at[0] = CellIndex{19, 0};   // border (within 2 rows of row 20)
  at[1] = CellIndex{17, 0};   // within reach of robot 0, larger index: deferred
  at[3] = CellIndex{15, 0};   // within reach of robot 1, larger index: deferred
  at[2] = CellIndex{13, 0};   // within reach of robot 3 only, smaller index: runs in phase 1
  for (int32_t k = 0; k < 9; ++k) at[static_cast<std::size_t>(17 - k)] = CellIndex{21 + 2 * k, 39};
  // Robot 17 (row 21) is a border robot; robot 16 above it has a smaller index: not deferred.
  BandSchedule b;
  ASSERT_TRUE(b.build(at, 40, 2, 2));
  const std::vector<int32_t> deferred(b.deferred().begin(), b.deferred().end());
  EXPECT_EQ(deferred, (std::vector<int32_t>{0, 1, 3, 17}));
  tbb::task_arena arena(2);
  const std::vector<int64_t> order = run_order(b, arena, at.size());
  for (std::size_t a = 0; a < at.size(); ++a)
    for (std::size_t c = a + 1; c < at.size(); ++c) {
      if (conflict(at[a], at[c], 2)) {
        EXPECT_LT(order[a], order[c]) << a << " " << c;
      }
    }
}

TEST(BandSchedule, DeclinesRobotsDenserThanOneWithinReachOfEach) {
  std::vector<CellIndex> at;
  for (int32_t i = 0; i < 32; ++i)
    for (int32_t j = 0; j < 32; j += 4) at.push_back(CellIndex{i, j});   // 256 robots on 32^2
  BandSchedule b;
  EXPECT_FALSE(b.build(at, 32, 2, 2));    // 256 x 25 > 1024 cells
  at.resize(40);
  EXPECT_TRUE(b.build(at, 32, 2, 2));     // 40 x 25 <= 1024
}
