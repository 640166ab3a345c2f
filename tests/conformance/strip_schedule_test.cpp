// The strip schedule (impl/exploration/strip_schedule.hpp) runs robots whose cells are within
// reach of each other (Chebyshev distance) in index order, whatever the threads: checked on the
// schedule itself, by the order in which it calls the work, on generated layouts; and again after
// a build on the same rows (the same cells, or cells moved along their rows), which keeps the last
// build's lists and only starts the strips again.
// Layouts range from sparse to crowded (narrow maps, many robots), so that strips set robots aside
// (and hit the limit of kMaxPending) and threads take over each other's strips.
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

using swarmcheck::exploration::CellIndex;

// Robots on a map of `map` rows and `columns` columns (not necessarily distinct cells: the schedule
// does not care).
std::vector<CellIndex> random_cells(int32_t map, int32_t columns, int32_t robots, uint64_t seed) {
  std::vector<CellIndex> cells(static_cast<std::size_t>(robots));
  for (std::size_t r = 0; r < cells.size(); ++r) {
    const uint64_t h = swarmcheck::exploration::splitmix64(seed + r);
    cells[r] = CellIndex{static_cast<int32_t>(h % static_cast<uint64_t>(map)),
                         static_cast<int32_t>((h >> 32) % static_cast<uint64_t>(columns))};
  }
  return cells;
}

// Every robot ran once, and robots whose cells are within reach ran in index order.
void check_order(const std::vector<CellIndex>& cells, int32_t reach, const std::vector<int64_t>& order) {
  for (std::size_t r = 0; r < cells.size(); ++r) RC_ASSERT(order[r] >= 0);
  for (std::size_t a = 0; a < cells.size(); ++a)
    for (std::size_t c = a + 1; c < cells.size(); ++c)
      if (std::abs(cells[a][0] - cells[c][0]) <= reach && std::abs(cells[a][1] - cells[c][1]) <= reach)
        RC_ASSERT(order[a] < order[c]);
}

}  // namespace

RC_GTEST_PROP(StripSchedule, ConflictingRobotsRunInIndexOrderOnAFreshBuildAndOnARebuildOfTheSameRows, ()) {
  const int32_t map = *rc::gen::inRange(4, 120);
  const int32_t columns = *rc::gen::inRange(1, 120);
  const int32_t reach = *rc::gen::inRange(1, 7);
  const int32_t strips = *rc::gen::inRange(2, 9);
  const int32_t robots = *rc::gen::inRange(2, 800);
  const auto seed = *rc::gen::arbitrary<uint64_t>();
  tbb::task_arena arena(*rc::gen::element(1, 2, 4));
  StripSchedule s;
  const std::vector<CellIndex> cells = random_cells(map, columns, robots, seed);
  const int32_t count = s.build(cells, map, reach, strips);
  if (count <= 1) RC_DISCARD("one strip");
  check_order(cells, reach, run_order(s, arena, cells.size()));
  // The same cells again: the lists are kept, and a second run must be as good as the first.
  RC_ASSERT(s.build(cells, map, reach, strips) == count);
  check_order(cells, reach, run_order(s, arena, cells.size()));
  // The same rows, other columns (the robots moved along their rows): the lists are kept, and the
  // robots set aside are judged by their new cells.
  std::vector<CellIndex> along = random_cells(map, columns, robots, seed + 77);
  for (std::size_t r = 0; r < along.size(); ++r) along[r][0] = cells[r][0];
  RC_ASSERT(s.build(along, map, reach, strips) == count);
  check_order(along, reach, run_order(s, arena, along.size()));
  // Other cells (the robots moved): a build of its own.
  const std::vector<CellIndex> moved = random_cells(map, columns, robots, seed + 1'000'003);
  if (s.build(moved, map, reach, strips) > 1) check_order(moved, reach, run_order(s, arena, moved.size()));
}
