// The strip schedule (impl/exploration/strip_schedule.hpp) runs robots whose rows are within
// reach of each other in index order, whatever the threads: checked on the schedule itself, by
// the order in which it calls the work, on generated layouts; and again after a build on the
// same rows, which keeps the last build's lists and only starts the strips again.
// (threads_test.cpp checks the simulation's bits.)
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <cstdlib>
#include <vector>

#include "impl/exploration/strip_schedule.hpp"
#include "spec/exploration/rng.hpp"
#include "tests/conformance/schedule_order.hpp"

using swarmcheck::impl::exploration::StripSchedule;

using swarmcheck::testing::run_order;

namespace {

const bool kSeededStripScheduleTest = [] { return ::setenv("RC_PARAMS", "seed=17", 0) == 0; }();

std::vector<int32_t> random_rows(int32_t map, int32_t robots, uint64_t seed) {
  std::vector<int32_t> rows(static_cast<std::size_t>(robots));
  for (std::size_t r = 0; r < rows.size(); ++r)
    rows[r] = static_cast<int32_t>(swarmcheck::exploration::splitmix64(seed + r) % static_cast<uint64_t>(map));
  return rows;
}

// Every robot ran once, and robots whose rows are within reach ran in index order.
void check_order(const std::vector<int32_t>& rows, int32_t reach, const std::vector<int64_t>& order) {
  for (std::size_t r = 0; r < rows.size(); ++r) RC_ASSERT(order[r] >= 0);
  for (std::size_t a = 0; a < rows.size(); ++a)
    for (std::size_t c = a + 1; c < rows.size(); ++c)
      if (std::abs(rows[a] - rows[c]) <= reach) RC_ASSERT(order[a] < order[c]);
}

}  // namespace

RC_GTEST_PROP(StripSchedule, ConflictingRobotsRunInIndexOrderOnAFreshBuildAndOnARebuildOfTheSameRows, ()) {
  const int32_t map = *rc::gen::inRange(4, 120);
  const int32_t reach = *rc::gen::inRange(1, 7);
  const int32_t strips = *rc::gen::inRange(2, 9);
  const int32_t robots = *rc::gen::inRange(2, 400);
  const auto seed = *rc::gen::arbitrary<uint64_t>();
  tbb::task_arena arena(*rc::gen::element(1, 2, 4));
  StripSchedule s;
  const std::vector<int32_t> rows = random_rows(map, robots, seed);
  const int32_t count = s.build(rows, map, reach, strips);
  if (count <= 1) RC_DISCARD("one strip");
  check_order(rows, reach, run_order(s, arena, rows.size()));
  // The same rows again: the lists are kept, and a second run must be as good as the first.
  RC_ASSERT(s.build(rows, map, reach, strips) == count);
  check_order(rows, reach, run_order(s, arena, rows.size()));
  // Other rows (the robots moved): a build of its own.
  const std::vector<int32_t> moved = random_rows(map, robots, seed + 1'000'003);
  if (s.build(moved, map, reach, strips) > 1) check_order(moved, reach, run_order(s, arena, moved.size()));
}
