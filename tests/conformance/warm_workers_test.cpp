// WarmWorkers (impl/exploration/warm_workers.hpp): parked workers spin between a step's parallel
// stages, and must let go of their threads, at wake() or by themselves after kSpinMax.
#include <gtest/gtest.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "impl/exploration/warm_workers.hpp"

namespace {

using swarmcheck::impl::exploration::WarmWorkers;
using Clock = std::chrono::steady_clock;

// Polls until pred() or the time is up (generous: a loaded CI machine may start a task late).
template <class Pred>
bool eventually(Pred pred, std::chrono::milliseconds limit = std::chrono::milliseconds(5000)) {
  const auto end = Clock::now() + limit;
  while (Clock::now() < end) {
    if (pred()) return true;
    std::this_thread::sleep_for(std::chrono::microseconds(50));
  }
  return pred();
}

TEST(WarmWorkers, AParkedWorkerLetsGoAtWakeAndTheArenaThenRunsParallelWork) {
  tbb::task_arena arena(2);
  WarmWorkers warm;
  warm.park(arena, 1);
  EXPECT_EQ(warm.spinning(), 1);   // handed out (started or not)
  warm.wake();
  EXPECT_TRUE(eventually([&] { return warm.spinning() == 0; }));
  std::atomic<int> done{0};
  arena.execute([&] { tbb::parallel_for(0, 1000, [&](int) { done.fetch_add(1); }); });
  EXPECT_EQ(done.load(), 1000);
}

TEST(WarmWorkers, AParkedWorkerNeverWokenStopsSpinningByItselfAfterTheLimit) {
  tbb::task_arena arena(2);
  WarmWorkers warm;
  warm.park(arena, 1);
  EXPECT_TRUE(eventually([&] { return warm.spinning() == 0; }));
}

TEST(WarmWorkers, ParkingTwiceWithoutAStageInBetweenLeavesNoTaskBehind) {
  tbb::task_arena arena(2);
  {
    WarmWorkers warm;
    warm.park(arena, 1);
    warm.park(arena, 1);
    EXPECT_EQ(warm.spinning(), 2);
    warm.wake();
    EXPECT_TRUE(eventually([&] { return warm.spinning() == 0; }));
  }
  // Destroyed while parked: the tasks hold the shared state, not the object.
  auto* warm = new WarmWorkers;
  warm->park(arena, 1);
  delete warm;
  std::atomic<int> done{0};
  arena.execute([&] { tbb::parallel_for(0, 100, [&](int) { done.fetch_add(1); }); });
  EXPECT_EQ(done.load(), 100);
}

}  // namespace
