#pragma once
// WarmWorkers: between two parallel stages of a step, the arena's worker threads spin for a
// while instead of going to sleep (OpenMP runtimes do the same: KMP_BLOCKTIME, GOMP_SPINCOUNT).
// A TBB worker that finds no work spins only briefly, then sleeps; between a step's stages the
// calling thread runs the sequential parts (the schedule's build, the deferred robots, the robots'
// records), some tens of microseconds, long enough for the workers to sleep, and a sleeping vCPU
// comes back late. After a stage, park() hands every worker a task that spins until the next
// stage's wake() (or kSpinMax, so an idle program does not burn a core). The tasks belong to a
// task_group that the destructor waits for (after waking them), so none outlives this object or
// is left in the arena's queue (a queued task that no thread ever ran leaked under LSan).
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <atomic>
#include <chrono>
#include <cstdint>

namespace swarmcheck::impl::exploration {

class WarmWorkers {
 public:
  static constexpr std::chrono::microseconds kSpinMax{1000};

  // `arena` must outlive this object.
  explicit WarmWorkers(tbb::task_arena& arena) : arena_(&arena) {}
  WarmWorkers(const WarmWorkers&) = delete;
  WarmWorkers& operator=(const WarmWorkers&) = delete;
  ~WarmWorkers() {
    wake();
    arena_->execute([&] { group_.wait(); });   // a task not yet started runs here and ends at once
  }

  // After a parallel stage: `workers` of the arena's worker threads spin until wake().
  void park(int32_t workers) {
    const uint64_t epoch = epoch_.load(std::memory_order_relaxed);
    arena_->execute([&] {
      for (int32_t k = 0; k < workers; ++k) {
        spinning_.fetch_add(1, std::memory_order_relaxed);
        group_.run([this, epoch] {
          // Only a worker spins: the calling thread (the arena's slot 0) may run a task it
          // spawned itself when it enters the arena again, and must not wait on it.
          const bool worker = tbb::this_task_arena::current_thread_index() != 0;
          const auto deadline = std::chrono::steady_clock::now() + kSpinMax;
          while (worker && epoch_.load(std::memory_order_relaxed) == epoch && std::chrono::steady_clock::now() < deadline)
            for (int i = 0; i < 64; ++i) pause();
          spinning_.fetch_sub(1, std::memory_order_relaxed);
        });
      }
    });
  }
  // Before the next parallel stage: the spinning tasks end (one not yet started ends at once).
  void wake() { epoch_.fetch_add(1, std::memory_order_relaxed); }
  // Spinning tasks handed out and not yet ended (for tests).
  int32_t spinning() const { return spinning_.load(std::memory_order_relaxed); }

 private:
  static void pause() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#elif defined(__aarch64__)
    asm volatile("yield");
#endif
  }
  tbb::task_arena* arena_;
  tbb::task_group group_;
  std::atomic<uint64_t> epoch_{0};
  std::atomic<int32_t> spinning_{0};
};

}  // namespace swarmcheck::impl::exploration
