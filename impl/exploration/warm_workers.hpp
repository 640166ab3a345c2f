#pragma once
// WarmWorkers: between two parallel stages of a step, the arena's worker threads spin for a
// while instead of going to sleep (OpenMP runtimes do the same: KMP_BLOCKTIME, GOMP_SPINCOUNT).
// A TBB worker that finds no work spins only briefly, then sleeps; between a step's stages the
// calling thread runs the sequential parts (the schedule's build, the deferred robots, the robots'
// records), some tens of microseconds, long enough for the workers to sleep. A sleeping vCPU
// comes back late and with cold caches: on a 2-core VM the worker's strip took 1.1-1.4x the
// calling thread's (same robots, strips swapped between the threads: the slowness followed the
// thread). After a stage, park() hands every worker a task that spins until the next stage's
// wake() (or kSpinMax, so an idle program does not burn a core).
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>

namespace swarmcheck::impl::exploration {

class WarmWorkers {
 public:
  static constexpr std::chrono::microseconds kSpinMax{1000};

  // After a parallel stage in `arena`: its `workers` worker threads spin until wake().
  void park(tbb::task_arena& arena, int32_t workers) {
    const uint64_t epoch = shared_->epoch.load(std::memory_order_relaxed);
    for (int32_t k = 0; k < workers; ++k) {
      shared_->spinning.fetch_add(1, std::memory_order_relaxed);
      arena.enqueue([shared = shared_, epoch] {   // outlives this object if need be
        const auto deadline = std::chrono::steady_clock::now() + kSpinMax;
        while (shared->epoch.load(std::memory_order_relaxed) == epoch &&
               std::chrono::steady_clock::now() < deadline)
          for (int i = 0; i < 64; ++i) pause();
        shared->spinning.fetch_sub(1, std::memory_order_relaxed);
      });
    }
  }
  // Before the next parallel stage: the spinning tasks end (one not yet started ends at once).
  void wake() { shared_->epoch.fetch_add(1, std::memory_order_relaxed); }
  // Spinning tasks handed out and not yet ended (for tests).
  int32_t spinning() const { return shared_->spinning.load(std::memory_order_relaxed); }

 private:
  static void pause() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#elif defined(__aarch64__)
    asm volatile("yield");
#endif
  }
  struct Shared {
    std::atomic<uint64_t> epoch{0};
    std::atomic<int32_t> spinning{0};
  };
  std::shared_ptr<Shared> shared_ = std::make_shared<Shared>();
};

}  // namespace swarmcheck::impl::exploration
