#pragma once
// What threads give, measured so that the machine's noise cannot make the ratio: one thread and
// every core run side by side, a block of steps (or passes) each in turn, each timed on its own,
// so both see the same neighbours and the same load. (On a shared 2-core VM, separate benchmark
// runs of identical code differ by 25 % and more, which a ratio of two separate runs inherits.)
// Blocks of `block` steps rather than single steps: a switch costs each side its caches and
// the idle side's worker threads fall asleep; with 16 steps of 10^4 robots a block, the switch is
// a few percent of a block. The counters: one_us and all_us per step, speedup = one_us / all_us.
//   threads/cli/...:     the options `swarmcheck run` uses by default (the tuner chooses) vs --threads 1
//   threads/strips/...:  the parallel schedules forced on every stage vs --threads 1
//   threads/ceiling/...: the decision stage's bare work split over the cores with no schedule
//                        (decision_ceiling.hpp) vs the same on one thread; share_slowdown: the
//                        slowest share's time (median) over its part of the one-thread pass
// Both simulations run the same scenario and, being bit-identical, stay in the same state; the
// bench checks that at the end (a change that makes one side cheaper by breaking it, e.g. robots
// that no longer move, would otherwise look like a speed-up) and reports an error if not.
#include <benchmark/benchmark.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <cstring>

#include "bench/exploration/decision_ceiling.hpp"
#include "swarmcheck/exploration.hpp"

namespace swarmcheck::bench {

class SideBySide {
 public:
  explicit SideBySide(int32_t block) : block_(block) {}
  template <class One, class All>
  void iteration(One&& one, All&& all) {
    const auto t0 = std::chrono::steady_clock::now();
    for (int32_t k = 0; k < block_; ++k) one();
    const auto t1 = std::chrono::steady_clock::now();
    for (int32_t k = 0; k < block_; ++k) all();
    const auto t2 = std::chrono::steady_clock::now();
    one_s_ += std::chrono::duration<double>(t1 - t0).count();
    all_s_ += std::chrono::duration<double>(t2 - t1).count();
    n_ += block_;
  }
  void report(benchmark::State& state) const {
    if (n_ == 0) return;
    state.counters["one_us"] = one_s_ / static_cast<double>(n_) * 1e6;
    state.counters["all_us"] = all_s_ / static_cast<double>(n_) * 1e6;
    state.counters["speedup"] = one_s_ / all_s_;
  }

 private:
  int32_t block_;
  double one_s_ = 0, all_s_ = 0;
  int64_t n_ = 0;
};

// Steps of 10^4 robots take about a millisecond, of 10^6 about a tenth of a second.
inline int32_t block_for(const exploration::Scenario& s) { return s.robots.size() >= 1'000'000 ? 2 : 16; }

// The two simulations' robots, visited cells and pheromone (by its digest) are the same bits.
inline bool same_state(const exploration::Exploration& a, const exploration::Exploration& b) {
  const auto ra = a.robots(), rb = b.robots();
  return a.steps() == b.steps() && a.visited() == b.visited() && ra.size() == rb.size() &&
         std::memcmp(ra.data(), rb.data(), ra.size_bytes()) == 0 &&
         a.record().pheromone_digest == b.record().pheromone_digest;
}

inline void bench_threads_steps(benchmark::State& state, const exploration::Scenario& s,
                                exploration::ExplorationOptions all_options) {
  exploration::ExplorationOptions one_options;
  one_options.threads = 1;
  exploration::Exploration one(s, one_options), all(s, all_options);
  SideBySide ab(block_for(s));
  for (auto _ : state) ab.iteration([&] { one.step(); }, [&] { all.step(); });
  if (!same_state(one, all)) state.SkipWithError("one thread and every core diverged: a bug, not a speed-up");
  ab.report(state);
}

inline void bench_threads_ceiling(benchmark::State& state, const exploration::Scenario& s) {
  DecisionCeiling ceiling(s);
  const int32_t cores = tbb::info::default_concurrency();
  tbb::task_arena one(1), all(cores);
  SideBySide ab(block_for(s));
  for (auto _ : state)
    ab.iteration([&] { benchmark::DoNotOptimize(ceiling.pass(one, 1)); },
                 [&] { benchmark::DoNotOptimize(ceiling.pass(all, cores)); });
  ab.report(state);
  // How much slower a share ran beside the others than its part of the one-thread pass: 1.0 is a
  // machine on which threads do not slow each other; the speed-up is then cores / this.
  const auto one_us = state.counters.find("one_us");
  if (cores > 1 && one_us != state.counters.end() && one_us->second.value > 0)
    state.counters["share_slowdown"] = ceiling.median_slowest_share_us() / (one_us->second.value / cores);
}

}  // namespace swarmcheck::bench
