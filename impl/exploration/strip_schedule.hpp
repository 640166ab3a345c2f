#pragma once
// Per-robot work of one stage (a decision, or a deposit) in parallel, with exactly the result of
// doing it robot by robot in index order.
//
// Robot r's work touches only cells within `radius` of its cell, so two robots conflict only when
// their cells are within reach = 2 * radius of each other (Chebyshev distance). The map's rows are
// cut into strips of at least reach + 1 rows (balanced by robot count), so robots of strips that
// are not neighbours never conflict. A robot within reach rows of a neighbouring strip's edge (a
// "border" robot) may run only once that neighbour has done every border robot of its own facing
// edge with a smaller index; a robot may run only once every robot of its own strip with a
// smaller index that it conflicts with has run. Any two conflicting robots are therefore done in
// index order, which is all the result depends on.
//
// A strip's own thread takes its robots in index order; one that may not run yet (a border robot
// whose neighbour is behind, or a robot conflicting with one set aside) is set aside, and the
// thread runs on, trying the set-aside robots again whenever a neighbour publishes progress; only
// with kMaxPending set aside, or at the strip's end, does it wait. (Waiting at every border robot
// instead tied the two threads to each other's pace: 10^4 robots on 256^2, strips forced, the
// waits were 15 % of the threads' time and the decisions ran at 1.1x one thread; now 1.45x.)
//
// Waiting never blocks on a thread that is not running: a strip is held by one thread at a time,
// and a thread that needs a neighbour nobody holds takes it and advances it itself, strictly in
// order. A thread waits only for its first set-aside robot, every robot of its strip before which
// is done, so a wait is always for a smaller robot index than anything the waited-for strip may
// be waiting for: there is no cycle, and the schedule is correct on any number of threads, one
// included, however the tasks are scheduled.
//
// The buffers are reused from step to step: no allocation once the sizes settle.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "spec/exploration/types.hpp"

namespace swarmcheck::impl::exploration {

// Cuts the rows [0, map_rows) into at most `strips` strips of at least reach + 1 rows each,
// balanced by the number of robots (cells[r] is robot r's cell). Fills row_count (robots per row)
// and lo (each strip's first row, then map_rows); returns the number of strips.
int32_t cut_strips(std::span<const swarmcheck::exploration::CellIndex> cells, int32_t map_rows, int32_t reach, int32_t strips,
                   std::vector<int32_t>& row_count, std::vector<int32_t>& lo);

class StripSchedule {
 public:
  // Cuts the rows [0, map_rows) into at most `strips` strips of at least reach + 1 rows each,
  // balanced by the number of robots (cells[r] is robot r's cell), and lists each strip's robots.
  // Returns the number of strips made (1 means: no parallelism to be had). Given the rows of the
  // last build again, it keeps that build's lists (10^6 robots: ~12 ms saved a step). `cells` is
  // read again by run(): it must outlive the run, unchanged.
  int32_t build(std::span<const swarmcheck::exploration::CellIndex> cells, int32_t map_rows, int32_t reach,
                int32_t strips);

  // Runs work(r, scratch) for every robot, in parallel over the strips in `arena`; the sum of what
  // work returns. `scratch` is a per-strip object of type Scratch, reused across steps. ahead(r)
  // is called a few robots before work(r) in the same strip (to prefetch what work will read).
  template <class Scratch, class Work, class Ahead>
  int64_t run(tbb::task_arena& arena, std::vector<Scratch>& scratch, Work&& work, Ahead&& ahead);

  // Robots a strip's own thread may set aside (a border robot whose neighbour is behind, and the
  // robots of its strip that conflict with one set aside) while it runs on. (With 32, 10^6 robots
  // on 1024^2 waited ~17 times a stage with a full list and ran ~8 % slower than before the
  // set-aside robots; with 256, about never.)
  static constexpr std::size_t kMaxPending = 256;

 private:
  static constexpr int32_t kNone = INT32_MAX;
  static constexpr int64_t kDone = -1;   // a pending entry that ran (removed after the pass)
  enum Side : int { kLower = 0, kUpper = 1 };

  // Two cache lines of its own: what the neighbours poll while they wait (held, next_border,
  // epoch), and what the strip's holder writes at every robot (pos, sum, pending). On one line,
  // each robot's write took the line back from a waiting neighbour's polling, so the strip ran
  // slower the more its neighbour waited (10^6 robots on 1024^2, strips forced, side by side over
  // three runs: 0.69-0.88x one thread; 0.85-0.96x with the lines apart).
  struct alignas(64) Strip {
    std::atomic<bool> held{false};
    // Per edge: the smallest index of the strip's border robots of that edge not yet done (kNone:
    // all done). A neighbour's border robot of a greater index waits for it.
    std::atomic<int32_t> next_border[2] = {kNone, kNone};
    // Bumped (and waiters woken) whenever next_border or held changes: a waiter reads it before
    // looking, and sleeps only if it has not moved since, so no wake-up is lost.
    std::atomic<uint32_t> epoch{0};
    alignas(64) int64_t begin = 0, end = 0, pos = 0;   // positions in members_, pos: next to take
    int64_t sum = 0;
    int64_t first_border[2] = {0, 0};   // per edge: the position of the strip's first border robot, or end
    int32_t lo = 0, hi = 0;              // its rows [lo, hi)
    // Set aside by the strip's own thread, ascending (only while it holds the strip: a helper
    // that holds it finds none, and takes robots strictly in order).
    std::vector<int64_t> pending;
    std::vector<int32_t> pending_in_row;   // per row - lo: how many of `pending` are on it
    int32_t seen_next[2] = {-1, -1};       // the neighbours' next_border when pending was last tried
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

  // The neighbour across `edge` of strip k has done its border robots below index `r`.
  bool neighbour_done(int32_t k, Side edge, int32_t r) const {
    const Strip& n = strips_[static_cast<std::size_t>(edge == kLower ? k - 1 : k + 1)];
    return n.next_border[edge == kLower ? kUpper : kLower].load(std::memory_order_acquire) >= r;
  }
  bool neighbours_done(int32_t k, int64_t p) const {
    const uint8_t b = border_[static_cast<std::size_t>(p)];
    const int32_t r = members_[static_cast<std::size_t>(p)];
    return (!(b & (1U << kLower)) || neighbour_done(k, kLower, r)) && (!(b & (1U << kUpper)) || neighbour_done(k, kUpper, r));
  }
  // The robots at positions p and q may touch a cell in common.
  bool conflict(int64_t p, int64_t q) const {
    const swarmcheck::exploration::CellIndex& a = cell_at(p);
    const swarmcheck::exploration::CellIndex& b = cell_at(q);
    return std::abs(a[0] - b[0]) <= reach_ && std::abs(a[1] - b[1]) <= reach_;
  }
  // The cell of the robot at position p (looked up only around set-aside robots: not tabled).
  const swarmcheck::exploration::CellIndex& cell_at(int64_t p) const {
    return cells_[static_cast<std::size_t>(members_[static_cast<std::size_t>(p)])];
  }
  // The robot at position p conflicts with one of the first `before` entries of s.pending still
  // pending.
  bool conflicts_pending(const Strip& s, int64_t p, std::size_t before) const;

  // Runs the robot at position p of strip k and publishes what it changed for the neighbours.
  template <class Scratch, class Work>
  void run_robot(int32_t k, int64_t p, std::vector<Scratch>& scratch, Work& work);
  // Publishes strip k's smallest not yet done border robot of each side in `sides` (bits).
  void publish(int32_t k, uint8_t sides);
  // Strip k's own thread: runs its robots, setting aside the ones that must wait.
  template <class Scratch, class Work, class Ahead>
  void run_own(int32_t k, std::vector<Scratch>& scratch, Work& work, Ahead& ahead);
  // Runs the pending robots of strip k that may run now; returns whether any did.
  template <class Scratch, class Work>
  bool try_pending(int32_t k, std::vector<Scratch>& scratch, Work& work);
  // A helper (or the own thread with nothing pending): strip k's next robot, strictly in order,
  // after its neighbours have done their earlier border robots.
  template <class Scratch, class Work, class Ahead>
  void do_next(int32_t k, std::vector<Scratch>& scratch, Work& work, Ahead& ahead);
  template <class Scratch, class Work, class Ahead>
  void wait_for(int32_t k, Side edge, int32_t index, std::vector<Scratch>& scratch, Work& work, Ahead& ahead);

  // Every strip back to its first robot, nobody holding it (after a build, before a run).
  void restart();

  int32_t count_ = 0;
  int32_t reach_ = 0;
  struct BuiltFor {
    int32_t map_rows = 0, reach = 0, strips = 0;
  } built_for_;
  std::vector<int32_t> built_rows_;       // the rows of the last build
  std::span<const swarmcheck::exploration::CellIndex> cells_;   // the cells of the last build (the caller's)
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

template <class Scratch, class Work>
void StripSchedule::run_robot(int32_t k, int64_t p, std::vector<Scratch>& scratch, Work& work) {
  Strip& s = strips_[static_cast<std::size_t>(k)];
  s.sum += work(members_[static_cast<std::size_t>(p)], scratch[static_cast<std::size_t>(k)]);
  if (const uint8_t b = border_[static_cast<std::size_t>(p)]) publish(k, b);
}

// Does strip k's next robot, after its neighbours have done their earlier border robots.
template <class Scratch, class Work, class Ahead>
void StripSchedule::do_next(int32_t k, std::vector<Scratch>& scratch, Work& work, Ahead& ahead) {
  Strip& s = strips_[static_cast<std::size_t>(k)];
  const int64_t p = s.pos;
  const int32_t r = members_[static_cast<std::size_t>(p)];
  if (p + kAhead < s.end) ahead(members_[static_cast<std::size_t>(p + kAhead)]);
  const uint8_t b = border_[static_cast<std::size_t>(p)];
  if (b & (1U << kLower)) wait_for(k - 1, kUpper, r, scratch, work, ahead);
  if (b & (1U << kUpper)) wait_for(k + 1, kLower, r, scratch, work, ahead);
  ++s.pos;   // before run_robot: its publishing looks from pos on
  run_robot(k, p, scratch, work);
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

template <class Scratch, class Work>
bool StripSchedule::try_pending(int32_t k, std::vector<Scratch>& scratch, Work& work) {
  Strip& s = strips_[static_cast<std::size_t>(k)];
  bool ran = false;
  for (std::size_t i = 0; i < s.pending.size(); ++i) {
    const int64_t p = s.pending[i];
    // Runs if its neighbours are done and it conflicts with none of the pending before it.
    if (!neighbours_done(k, p) || conflicts_pending(s, p, i)) continue;
    --s.pending_in_row[static_cast<std::size_t>(cell_at(p)[0] - s.lo)];
    s.pending[i] = kDone;   // before run_robot publishes: the smallest border robot still pending counts
    run_robot(k, p, scratch, work);
    ran = true;
  }
  if (ran) std::erase(s.pending, kDone);
  return ran;
}

template <class Scratch, class Work, class Ahead>
void StripSchedule::run_own(int32_t k, std::vector<Scratch>& scratch, Work& work, Ahead& ahead) {
  Strip& s = strips_[static_cast<std::size_t>(k)];
  for (int64_t q = s.pos; q < std::min(s.end, s.pos + kAhead); ++q) ahead(members_[static_cast<std::size_t>(q)]);
  for (;;) {
    if (!s.pending.empty()) {
      // Tried again when a neighbour has moved on since the last try.
      const int32_t lower = k > 0 ? strips_[static_cast<std::size_t>(k) - 1].next_border[kUpper].load(std::memory_order_acquire) : kNone;
      const int32_t upper = k + 1 < count_ ? strips_[static_cast<std::size_t>(k) + 1].next_border[kLower].load(std::memory_order_acquire) : kNone;
      if (lower != s.seen_next[kLower] || upper != s.seen_next[kUpper]) {
        s.seen_next[kLower] = lower;
        s.seen_next[kUpper] = upper;
        try_pending(k, scratch, work);
      }
    }
    if (s.pos < s.end && s.pending.size() < kMaxPending) {
      const int64_t p = s.pos++;
      if (p + kAhead < s.end) ahead(members_[static_cast<std::size_t>(p + kAhead)]);
      const bool must_wait = (!s.pending.empty() && conflicts_pending(s, p, s.pending.size())) ||
                             (border_[static_cast<std::size_t>(p)] && !neighbours_done(k, p));
      if (must_wait) {
        s.pending.push_back(p);
        ++s.pending_in_row[static_cast<std::size_t>(cell_at(p)[0] - s.lo)];
      } else {
        run_robot(k, p, scratch, work);
      }
      continue;
    }
    if (s.pending.empty()) return;   // all done
    // Nothing more to take (the end, or too many set aside): wait for the first pending robot's
    // neighbours (advancing them if nobody holds them). Everything of this strip before it is done,
    // as the in-order schedule requires of a waiter, so no wait is ever circular.
    const int64_t head = s.pending.front();
    const int32_t r = members_[static_cast<std::size_t>(head)];
    const uint8_t b = border_[static_cast<std::size_t>(head)];
    if (b & (1U << kLower)) wait_for(k - 1, kUpper, r, scratch, work, ahead);
    if (b & (1U << kUpper)) wait_for(k + 1, kLower, r, scratch, work, ahead);
    try_pending(k, scratch, work);   // the head runs now: nothing before it is pending
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
        run_own(k, scratch, work, ahead);
        release(s);
      }
    }, affinity_);
  });
  int64_t total = 0;
  for (int32_t k = 0; k < count_; ++k) total += strips_[static_cast<std::size_t>(k)].sum;
  return total;
}

}  // namespace swarmcheck::impl::exploration
