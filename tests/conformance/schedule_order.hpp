#pragma once
// The order in which a parallel schedule (band_schedule.hpp, strip_schedule.hpp) calls its work:
// the position in the run at which each robot's work was done (-1: never), with the run's sum
// checked to be one per robot. Shared by the schedules' property tests.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <cstdint>
#include <vector>

namespace swarmcheck::testing {

template <class Schedule>
std::vector<int64_t> run_order(Schedule& s, tbb::task_arena& arena, std::size_t robots) {
  std::atomic<int64_t> clock{0};
  std::vector<int64_t> at(robots, -1);
  std::vector<char> scratch;
  const int64_t sum = s.run(arena, scratch, [&](int32_t r, char&) {
    at[static_cast<std::size_t>(r)] = clock.fetch_add(1);
    return int64_t{1};
  }, [](int32_t) {});
  EXPECT_EQ(sum, static_cast<int64_t>(robots));
  return at;
}

}  // namespace swarmcheck::testing
