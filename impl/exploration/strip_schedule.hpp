#pragma once
// Per-robot work of one stage (a decision, or a deposit) in parallel, with exactly the result of
// doing it robot by robot in index order.
//
// Robot r's work touches only cells within `radius` rows of its row, so two robots conflict only
// when their rows are within reach = 2 * radius. The map's rows are cut into strips of at least
// reach + 1 rows (balanced by robot count), so robots of strips that are not neighbours never
// conflict. Each strip runs its robots in index order; a robot within reach of a neighbouring
// strip's edge (a "border" robot) first waits until that neighbour has done every border robot
// of its own facing edge with a smaller index. Any two conflicting robots are therefore done in
// index order, which is all the result depends on.
//
// Waiting never blocks on a thread that is not running: a strip is held by one thread at a time,
// and a thread that needs a neighbour nobody holds takes it and advances it itself. A wait is
// always for a smaller robot index, so there is no cycle, and the schedule is correct on any
// number of threads, one included, however the tasks are scheduled.
//
// The buffers are reused from step to step: no allocation once the sizes settle.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "spec/exploration/types.hpp"

namespace swarmcheck::impl::exploration {

// Cuts the rows [0, map_rows) into at most `strips` strips of at least reach + 1 rows each,
// balanced by the number of robots (rows[r] is robot r's row). Fills row_count (robots per row)
// and lo (each strip's first row, then map_rows); returns the number of strips.
int32_t cut_strips(std::span<const int32_t> rows, int32_t map_rows, int32_t reach, int32_t strips,
                   std::vector<int32_t>& row_count, std::vector<int32_t>& lo);

class StripSchedule {
 public:
  // Cuts the rows [0, map_rows) into at most `strips` strips of at least reach + 1 rows each,
  // balanced by the number of robots (rows[r] is robot r's row), and lists each strip's robots.
  // Returns the number of strips made (1 means: no parallelism to be had). Given the rows of
  // the last build again, it keeps that build's lists (10^6 robots: ~12 ms saved a step).
  int32_t build(std::span<const int32_t> rows, int32_t map_rows, int32_t reach, int32_t strips);

  // Runs work(r, scratch) for every robot, in parallel over the strips in `arena`; the sum of what
  // work returns. `scratch` is a per-strip object of type Scratch, reused across steps. ahead(r)
  // is called a few robots before work(r) in the same strip (to prefetch what work will read).
  template <class Scratch, class Work, class Ahead>
  int64_t run(tbb::task_arena& arena, std::vector<Scratch>& scratch, Work&& work, Ahead&& ahead);

 private:
  static constexpr int32_t kNone = INT32_MAX;
  enum Side : int { kLower = 0, kUpper = 1 };

  // Two cache lines of its own: what the neighbours poll while they wait (held, next_border,
  // epoch), and what the strip's holder writes at every robot (pos, sum). On one line, each
  // robot's write took the line back from a waiting neighbour's polling, so the strip ran slower
  // the more its neighbour waited (10^6 robots on 1024^2, strips forced, side by side over three
  // runs: 0.69-0.88x one thread; 0.85-0.96x with the lines apart).
  struct alignas(64) Strip {
    std::atomic<bool> held{false};
    std::atomic<int32_t> next_border[2] = {kNone, kNone};   // next robot index not yet done, per edge
    // Bumped (and waiters woken) whenever next_border or held changes: a waiter reads it before
    // looking, and sleeps only if it has not moved since, so no wake-up is lost.
    std::atomic<uint32_t> epoch{0};
    alignas(64) int64_t begin = 0, end = 0, pos = 0;   // positions in members_, pos: next to do
    int64_t sum = 0;
    int64_t first_border[2] = {0, 0};   // per edge: the position of the strip's first border robot, or end
  };

  bool try_hold(Strip& s) { return !s.held.exchange(true, std::memory_order_acquire); }
  static void changed(Strip& s) {
    s.epoch.fetch_add(1, std::memory_order_release);
    s.epoch.notify_all();
  }
  static void release(Strip& s) {
    s.held.store(false, std::memory_order_release);
    changed(s);
  }
  // A spin of some tens of microseconds (the neighbour is usually a few robots behind, and a
  // sleep and wake-up costs about that much), then sleep until the strip changes: a thread that
  // waits longer never takes a core from the thread it waits for.
  static void wait_change(Strip& s, uint32_t seen, int& spins) {
    if (++spins < kSpinsBeforeSleep) {
      cpu_relax();
      return;
    }
    s.epoch.wait(seen, std::memory_order_acquire);
  }
  static void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#elif defined(__aarch64__)
    asm volatile("yield");
#endif
  }
  static constexpr int kSpinsBeforeSleep = 2048;
  static constexpr int64_t kAhead = 4;   // robots

  template <class Scratch, class Work, class Ahead>
  void do_next(int32_t k, std::vector<Scratch>& scratch, Work& work, Ahead& ahead);
  template <class Scratch, class Work, class Ahead>
  void wait_for(int32_t k, Side edge, int32_t index, std::vector<Scratch>& scratch, Work& work, Ahead& ahead);

  // Every strip back to its first robot, nobody holding it (after a build, before a run).
  void restart();

  int32_t count_ = 0;
  struct BuiltFor {
    int32_t map_rows = 0, reach = 0, strips = 0;
  } built_for_;
  std::vector<int32_t> built_rows_;       // the rows of the last build
  tbb::affinity_partitioner affinity_;   // strip k on the thread that had it last time (its cells' cache)
  std::unique_ptr<Strip[]> strips_;
  int32_t capacity_ = 0;
  std::vector<int32_t> row_count_, lo_;   // robots per row; first row of each strip (+ map_rows)
  std::vector<int32_t> row_strip_;        // per row: its strip
  std::vector<uint8_t> row_border_;       // per row: bit kLower, bit kUpper (within reach of that edge)
  std::vector<int32_t> members_;          // robot indices, strip by strip, ascending in a strip
  std::vector<uint8_t> border_;           // per position: bit kLower, bit kUpper
  std::vector<int64_t> start_, fill_;         // each strip's first position; the filling cursor
};

// Does strip k's next robot, after its neighbours have done their earlier border robots.
template <class Scratch, class Work, class Ahead>
void StripSchedule::do_next(int32_t k, std::vector<Scratch>& scratch, Work& work, Ahead& ahead) {
  Strip& s = strips_[static_cast<std::size_t>(k)];
  const auto p = static_cast<std::size_t>(s.pos);
  const int32_t r = members_[p];
  if (s.pos + kAhead < s.end) ahead(members_[p + kAhead]);
  if (border_[p] & (1U << kLower)) wait_for(k - 1, kUpper, r, scratch, work, ahead);
  if (border_[p] & (1U << kUpper)) wait_for(k + 1, kLower, r, scratch, work, ahead);
  s.sum += work(r, scratch[static_cast<std::size_t>(k)]);
  ++s.pos;
  // The robot was the next border robot of its edges: publish the one after it (release: its
  // cells are written before a neighbour reads that it is done). Found by a scan of the border
  // bytes here, in the parallel stage, rather than tabled by build() on the calling thread: the
  // scans of a stage cover each strip once per edge.
  for (int side : {kLower, kUpper})
    if (border_[p] & (1U << side)) {
      auto q = static_cast<std::size_t>(s.pos);
      const auto end = static_cast<std::size_t>(s.end);
      while (q < end && !(border_[q] & (1U << side))) ++q;
      s.next_border[side].store(q < end ? members_[q] : kNone, std::memory_order_release);
      changed(s);
    }
}

// Returns once strip k has done every robot of its `edge` border with an index below `index`,
// advancing the strip itself when no thread holds it.
template <class Scratch, class Work, class Ahead>
void StripSchedule::wait_for(int32_t k, Side edge, int32_t index, std::vector<Scratch>& scratch, Work& work,
                             Ahead& ahead) {
  Strip& s = strips_[static_cast<std::size_t>(k)];
  int spins = 0;
  for (;;) {
    const uint32_t seen = s.epoch.load(std::memory_order_acquire);
    if (s.next_border[edge].load(std::memory_order_acquire) >= index) return;
    if (try_hold(s)) {
      while (s.next_border[edge].load(std::memory_order_relaxed) < index) do_next(k, scratch, work, ahead);
      release(s);
      return;
    }
    wait_change(s, seen, spins);
  }
}

template <class Scratch, class Work, class Ahead>
int64_t StripSchedule::run(tbb::task_arena& arena, std::vector<Scratch>& scratch, Work&& work, Ahead&& ahead) {
  if (scratch.size() < static_cast<std::size_t>(count_)) scratch.resize(static_cast<std::size_t>(count_));
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int32_t>(0, count_, 1), [&](const tbb::blocked_range<int32_t>& range) {
      for (int32_t k = range.begin(); k < range.end(); ++k) {
        Strip& s = strips_[static_cast<std::size_t>(k)];
        int spins = 0;
        for (;;) {   // a helper may hold it for a while; this task finishes the rest
          const uint32_t seen = s.epoch.load(std::memory_order_acquire);
          if (try_hold(s)) break;
          wait_change(s, seen, spins);
        }
        for (int64_t q = s.pos; q < std::min(s.end, s.pos + kAhead); ++q) ahead(members_[static_cast<std::size_t>(q)]);
        while (s.pos < s.end) do_next(k, scratch, work, ahead);
        release(s);
      }
    }, affinity_);
  });
  int64_t total = 0;
  for (int32_t k = 0; k < count_; ++k) total += strips_[static_cast<std::size_t>(k)].sum;
  return total;
}

}  // namespace swarmcheck::impl::exploration
