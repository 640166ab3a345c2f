// WarmWorkers (impl/exploration/warm_workers.hpp): parked workers spin between a step's parallel
// stages, and must let go of their threads, at wake() or by themselves after kSpinMax, and leave
// no task behind when destroyed.
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
  WarmWorkers warm(arena);
  warm.park(1);
  EXPECT_LE(warm.spinning(), 1);   // handed out (started or not; it ends by itself after kSpinMax)
  warm.wake();
  EXPECT_TRUE(eventually([&] { return warm.spinning() == 0; }));
  std::atomic<int> done{0};
  arena.execute([&] { tbb::parallel_for(0, 1000, [&](int) { done.fetch_add(1); }); });
  EXPECT_EQ(done.load(), 1000);
}

TEST(WarmWorkers, AParkedWorkerNeverWokenStopsSpinningByItselfAfterTheLimit) {
  tbb::task_arena arena(2);
  WarmWorkers warm(arena);
  warm.park(1);
  EXPECT_TRUE(eventually([&] { return warm.spinning() == 0; }));
}

TEST(WarmWorkers, ParkingTwiceWithoutAStageInBetweenLeavesNoTaskBehind) {
  tbb::task_arena arena(2);
  WarmWorkers warm(arena);
  warm.park(1);
  warm.park(1);   // the calling thread may run the first task itself: it must not spin on it
  EXPECT_LE(warm.spinning(), 2);
  warm.wake();
  EXPECT_TRUE(eventually([&] { return warm.spinning() == 0; }));
}

TEST(WarmWorkers, DestroyedWhileParkedItWaitsForItsTasksSoNoneIsLeftInTheArena) {
  tbb::task_arena arena(2);
  for (int k = 0; k < 50; ++k) {
    WarmWorkers warm(arena);
    warm.park(1);
    warm.park(1);
  }   // each destructor wakes and waits: LSan (build-debug) finds nothing left behind
  std::atomic<int> done{0};
  arena.execute([&] { tbb::parallel_for(0, 100, [&](int) { done.fetch_add(1); }); });
  EXPECT_EQ(done.load(), 100);
}

}  // namespace
