#pragma once
// Per-robot work of one stage in parallel with no waiting between threads, and exactly the
// result of doing it robot by robot in index order, for sparse robots.
//
// As in strip_schedule.hpp, robots conflict (may touch a cell in common) only when their cells
// are within `reach` of each other (Chebyshev distance), and the map's rows are cut into strips.
// A robot within reach rows of a strip edge is a *border* robot; a robot is *deferred* when it is
// a border robot, or conflicts with a deferred robot of smaller index (the closure follows chains
// of increasing index). The stage then runs
//   1. in parallel, each strip's robots that are not deferred, in index order;
//   2. on the calling thread, the deferred robots in index order.
// Any two conflicting robots a < b still run in index order: if neither is deferred they are in
// one strip (a robot that is not a border robot conflicts with none of another strip) and phase 1
// keeps their order; b deferred and a not runs b later; a deferred makes b deferred.
//
// The closure grows with density (it follows chains of conflicting robots), so build() declines
// where it would be large: the expected number of robots within reach of one (robots x (2 reach +
// 1)^2 / cells) above kMaxNeighbours, or more than 1 / kMaxDeferredShare of the robots deferred
// (and more than kMinDeferredCap).
// There the strip schedule (waiting at the edges) is the parallel alternative.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "spec/exploration/types.hpp"

namespace swarmcheck::impl::exploration {

class BandSchedule {
 public:
  static constexpr double kMaxNeighbours = 1.0;
  static constexpr int64_t kMaxDeferredShare = 8;
  static constexpr int64_t kMinDeferredCap = 256;   // few robots: deferring them all costs little

  // cells[r] is robot r's cell on a map_size^2 map. Returns false (and nothing to run) when
  // there would be one strip only, or the robots are too dense (above).
  bool build(std::span<const swarmcheck::exploration::CellIndex> cells, int32_t map_size, int32_t reach,
             int32_t strips);

  // Runs work(r, scratch) for every robot (phase 1 over the strips in `arena`, then phase 2 with
  // scratch[0]); the sum of what work returns. ahead(r) is called a few robots before work(r).
  template <class Scratch, class Work, class Ahead>
  int64_t run(tbb::task_arena& arena, std::vector<Scratch>& scratch, Work&& work, Ahead&& ahead);

  // The robots the last build() deferred to phase 2, in index order.
  std::span<const int32_t> deferred() const { return deferred_; }

 private:
  static constexpr std::size_t kAhead = 4;   // robots

  template <class Scratch, class Work, class Ahead>
  static int64_t run_list(std::span<const int32_t> list, Scratch& scratch, Work& work, Ahead& ahead) {
    int64_t sum = 0;
    for (std::size_t q = 0; q < std::min(list.size(), kAhead); ++q) ahead(list[q]);
    for (std::size_t p = 0; p < list.size(); ++p) {
      if (p + kAhead < list.size()) ahead(list[p + kAhead]);
      sum += work(list[p], scratch);
    }
    return sum;
  }

  int32_t count_ = 0;
  std::vector<int32_t> rows_, row_count_, lo_, strip_of_row_;
  std::vector<int32_t> row_start_, by_row_;      // robots bucketed by row, index order in a row
  std::vector<int32_t> by_row_column_;           // the column of each by_row_ entry
  std::vector<uint8_t> is_deferred_;
  std::vector<int32_t> queue_, deferred_;        // the closure's work list; deferred, index order
  std::vector<int64_t> start_;                   // each strip's first position in members_
  std::vector<int32_t> members_;                 // phase 1: strip by strip, index order
  // Replays the last run's mapping of strips to threads, so that a strip's cells stay in the
  // cache of the core that worked on them (robots move little from step to step).
  tbb::affinity_partitioner affinity_;
  std::vector<int64_t> sums_, fill_;             // per strip: the last run's sums; a cursor
};

template <class Scratch, class Work, class Ahead>
int64_t BandSchedule::run(tbb::task_arena& arena, std::vector<Scratch>& scratch, Work&& work, Ahead&& ahead) {
  if (scratch.size() < static_cast<std::size_t>(count_)) scratch.resize(static_cast<std::size_t>(count_));
  std::vector<int64_t>& sums = sums_;
  sums.assign(static_cast<std::size_t>(count_), 0);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int32_t>(0, count_, 1), [&](const tbb::blocked_range<int32_t>& range) {
      for (int32_t k = range.begin(); k < range.end(); ++k) {
        const auto b = static_cast<std::size_t>(start_[static_cast<std::size_t>(k)]);
        const auto e = static_cast<std::size_t>(start_[static_cast<std::size_t>(k) + 1]);
        sums[static_cast<std::size_t>(k)] = run_list(std::span<const int32_t>(members_).subspan(b, e - b),
                                                     scratch[static_cast<std::size_t>(k)], work, ahead);
      }
    }, affinity_);
  });
  int64_t total = run_list(std::span<const int32_t>(deferred_), scratch[0], work, ahead);
  for (int64_t s : sums) total += s;
  return total;
}

}  // namespace swarmcheck::impl::exploration
