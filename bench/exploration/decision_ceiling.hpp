#pragma once
// The machine's ceiling for threads on the decision stage: every robot's gather and choice
// (spec::gather_candidates + spec::choose on the impl's LazyGrid), read-only, with the robots cut
// into one contiguous share per thread and no schedule at all: no bands, no strips, no waiting,
// no applying of the decisions. No correct schedule does less work than this, so its speed-up
// from threads bounds what the decision stage can gain on this machine (threads/ceiling/... in
// threads_ab.hpp runs it on one thread and on every core, side by side).
// Each share is timed on its thread: a share of 1/k of the robots should take 1/k of the pass
// on one thread. When shares run together they take longer than that (at times 1.6x, on both
// threads at once, with nothing shared but the read-only grid), the machine is slowing threads
// that run together (its memory system, or a host that places the two vCPUs on one core), and
// no schedule can win that back.
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <vector>

#include "impl/exploration/cache_line_allocator.hpp"
#include "impl/exploration/lazy_grid.hpp"
#include "spec/exploration/environment_step.hpp"

namespace swarmcheck::bench {

class DecisionCeiling {
 public:
  explicit DecisionCeiling(const exploration::Scenario& s)
      : cfg_(exploration::make_environment_config(s)),
        grid_(cfg_),
        env_(exploration::initial_environment(cfg_, grid_)) {}

  // One read-only decision pass over every robot with `threads` equal shares; returns a digest
  // of the choices (so that nothing is optimised away).
  int64_t pass(tbb::task_arena& arena, int32_t threads) {
    const int64_t n = static_cast<int64_t>(env_.robots.size());
    scratch_.resize(static_cast<std::size_t>(threads));
    sums_.assign(static_cast<std::size_t>(threads), 0);
    share_us_.resize(static_cast<std::size_t>(threads));
    arena.execute([&] {
      tbb::parallel_for(0, threads, [&](int32_t k) {
        const auto t0 = std::chrono::steady_clock::now();
        auto& c = scratch_[static_cast<std::size_t>(k)].c;
        int64_t sum = 0;
        for (int64_t r = n * k / threads; r < n * (k + 1) / threads; ++r) {
          const exploration::CellIndex cell = env_.robots[static_cast<std::size_t>(r)].cell;
          exploration::gather_candidates(cfg_, grid_, cell, env_.tick, c);
          sum += exploration::choose(*cfg_.rules, cfg_.terms, c,
                                     exploration::DrawSite{cfg_.scenario.seed, env_.tick, static_cast<int32_t>(r)})
                     .target;
        }
        sums_[static_cast<std::size_t>(k)] = sum;
        share_us_[static_cast<std::size_t>(k)] =
            std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
      }, tbb::static_partitioner{});
    });
    if (threads > 1) shares_.push_back(*std::max_element(share_us_.begin(), share_us_.end()));
    int64_t total = 0;
    for (int64_t v : sums_) total += v;
    return total;
  }

  // The median over the passes on more than one thread of the slowest share's time (us).
  double median_slowest_share_us() const {
    if (shares_.empty()) return 0.0;
    std::vector<double> v = shares_;
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    return v[v.size() / 2];
  }

 private:
  exploration::EnvironmentConfig cfg_;
  impl::exploration::LazyGrid grid_;
  exploration::EnvironmentState env_;
  // As impl's strips keep theirs: a buffer that shares a cache line with the other thread's
  // costs the pass all its speed-up from threads (0.99x against 1.9x, 10^4 robots on 1024^2).
  struct alignas(impl::exploration::kCacheLine) Scratch {
    std::vector<exploration::Candidate, impl::exploration::CacheLineAllocator<exploration::Candidate>> c;
  };
  std::vector<Scratch> scratch_;
  std::vector<int64_t> sums_;
  std::vector<double> share_us_;   // the last pass's, per share
  std::vector<double> shares_;     // per pass on more than one thread: its slowest share
};

}  // namespace swarmcheck::bench
