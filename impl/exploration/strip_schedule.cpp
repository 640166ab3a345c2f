#include "impl/exploration/strip_schedule.hpp"

#include <algorithm>

namespace swarmcheck::impl::exploration {

int32_t cut_strips(std::span<const swarmcheck::exploration::CellIndex> cells, int32_t map_rows, int32_t reach,
                   int32_t strips, std::vector<int32_t>& row_count, std::vector<int32_t>& lo) {
  const int64_t n = static_cast<int64_t>(cells.size());
  const int64_t min_height = int64_t{reach} + 1;
  // Strip boundaries at robot-count quantiles of the rows, each strip at least min_height rows.
  row_count.assign(static_cast<std::size_t>(map_rows), 0);
  for (const swarmcheck::exploration::CellIndex& c : cells) ++row_count[static_cast<std::size_t>(c[0])];
  lo.clear();
  lo.push_back(0);
  const int64_t per_strip = std::max<int64_t>(1, (n + strips - 1) / std::max(1, strips));
  int64_t in_strip = 0;
  for (int32_t i = 0; i < map_rows; ++i) {
    if (in_strip >= per_strip && i - lo.back() >= min_height && map_rows - i >= min_height) {
      lo.push_back(i);
      in_strip = 0;
    }
    in_strip += row_count[static_cast<std::size_t>(i)];
  }
  const auto count = static_cast<int32_t>(lo.size());
  lo.push_back(map_rows);
  return count;
}

namespace {
bool same_rows(std::span<const swarmcheck::exploration::CellIndex> cells, const std::vector<int32_t>& rows) {
  if (cells.size() != rows.size()) return false;
  for (std::size_t r = 0; r < rows.size(); ++r)
    if (cells[r][0] != rows[r]) return false;
  return true;
}
}  // namespace

int32_t StripSchedule::build(std::span<const swarmcheck::exploration::CellIndex> cells, int32_t map_rows,
                             int32_t reach, int32_t strips) {
  // The same rows as the last build (a step's deposit centres are, under most rules, the cells the
  // next step's robots decide from): its lists hold, only the strips' progress starts again.
  cells_ = cells;
  reach_ = reach;
  if (count_ > 0 && map_rows == built_for_.map_rows && reach == built_for_.reach && strips == built_for_.strips &&
      same_rows(cells, built_rows_)) {
    restart();
    return count_;
  }
  built_for_ = {map_rows, reach, strips};
  built_rows_.resize(cells.size());   // filled by the members' pass below
  const int64_t n = static_cast<int64_t>(cells.size());
  count_ = cut_strips(cells, map_rows, reach, strips, row_count_, lo_);
  if (count_ > capacity_) {
    strips_ = std::make_unique<Strip[]>(static_cast<std::size_t>(count_));
    capacity_ = count_;
  }
  // Per row: its strip and its border bits (a row within reach of the strip below or above), so
  // that each robot costs two table reads; then the members strip by strip in index order. (With
  // the tests per robot, and the cursors behind references that every byte store might alias,
  // this loop was most of a 68 us build at 10^4 robots.)
  std::vector<int64_t>& start = start_;
  start.assign(static_cast<std::size_t>(count_) + 1, 0);
  row_strip_.resize(static_cast<std::size_t>(map_rows));
  row_border_.resize(static_cast<std::size_t>(map_rows));
  for (int32_t k = 0; k < count_; ++k) {
    const int32_t lo = lo_[static_cast<std::size_t>(k)], hi = lo_[static_cast<std::size_t>(k) + 1];
    for (int32_t i = lo; i < hi; ++i) {
      start[static_cast<std::size_t>(k) + 1] += row_count_[static_cast<std::size_t>(i)];
      row_strip_[static_cast<std::size_t>(i)] = k;
      uint8_t b = 0;
      if (k > 0 && i - lo < reach) b |= 1U << kLower;                   // within reach of the strip below
      if (k + 1 < count_ && hi - 1 - i < reach) b |= 1U << kUpper;      // or above
      row_border_[static_cast<std::size_t>(i)] = b;
    }
  }
  for (int32_t k = 0; k < count_; ++k) start[static_cast<std::size_t>(k) + 1] += start[static_cast<std::size_t>(k)];
  members_.resize(static_cast<std::size_t>(n));
  border_.resize(static_cast<std::size_t>(n));
  std::vector<int64_t>& fill = fill_;
  fill.assign(start.begin(), start.end() - 1);
  {
    int64_t* const cursor = fill.data();
    int32_t* const members = members_.data();
    uint8_t* const border = border_.data();
    const int32_t* const strip_of = row_strip_.data();
    const uint8_t* const border_of = row_border_.data();
    int32_t* const built_row = built_rows_.data();
    const swarmcheck::exploration::CellIndex* const cell = cells.data();
    for (int64_t r = 0; r < n; ++r) {
      const int32_t i = cell[r][0];
      built_row[r] = i;
      const int64_t p = cursor[strip_of[i]]++;
      members[p] = static_cast<int32_t>(r);
      border[p] = border_of[i];
    }
  }
  for (int32_t k = 0; k < count_; ++k) {
    Strip& s = strips_[static_cast<std::size_t>(k)];
    s.begin = start[static_cast<std::size_t>(k)];
    s.end = start[static_cast<std::size_t>(k) + 1];
    s.lo = lo_[static_cast<std::size_t>(k)];
    s.hi = lo_[static_cast<std::size_t>(k) + 1];
    s.pending.reserve(kMaxPending);
    s.pending_in_row.assign(static_cast<std::size_t>(s.hi - s.lo), 0);
    // Per edge: the strip's first border robot's position (or end), found by a scan; the map's
    // own edges have none.
    for (int side : {kLower, kUpper}) {
      const bool edge = side == kLower ? k > 0 : k + 1 < count_;
      int64_t q = edge ? s.begin : s.end;
      while (q < s.end && !(border_[static_cast<std::size_t>(q)] & (1U << side))) ++q;
      s.first_border[side] = q;
    }
  }
  restart();
  return count_;
}

void StripSchedule::restart() {
  for (int32_t k = 0; k < count_; ++k) {
    Strip& s = strips_[static_cast<std::size_t>(k)];
    s.held.store(false, std::memory_order_relaxed);
    s.pos = s.begin;
    s.sum = 0;
    s.pending.clear();   // empty after every run; cleared for a run that threw
    std::fill(s.pending_in_row.begin(), s.pending_in_row.end(), 0);
    s.seen_next[kLower] = s.seen_next[kUpper] = -1;
    for (int side : {kLower, kUpper}) {
      const int64_t q = s.first_border[side];
      s.next_border[side].store(q < s.end ? members_[static_cast<std::size_t>(q)] : kNone, std::memory_order_relaxed);
    }
  }
}

bool StripSchedule::conflicts_pending(const Strip& s, int64_t p, std::size_t before) const {
  // Most robots have no pending robot within reach of their row: a look at the row counts.
  const int32_t row = cell_at(p)[0];
  const int32_t i0 = std::max(s.lo, row - reach_), i1 = std::min(s.hi - 1, row + reach_);
  bool near = false;
  for (int32_t i = i0; i <= i1 && !near; ++i) near = s.pending_in_row[static_cast<std::size_t>(i - s.lo)] > 0;
  if (!near) return false;
  for (std::size_t j = 0; j < before; ++j)
    if (s.pending[j] != kDone && conflict(p, s.pending[j])) return true;
  return false;
}

void StripSchedule::publish(int32_t k, uint8_t sides) {
  Strip& s = strips_[static_cast<std::size_t>(k)];
  for (int side : {kLower, kUpper}) {
    if (!(sides & (1U << side))) continue;
    // The smallest not yet done: a pending one (they come before pos, ascending), else the next
    // at or after pos. Found by a scan of the border bytes here, in the parallel stage, rather
    // than tabled by build() on the calling thread: the scans of a stage cover each strip once
    // per edge.
    int32_t next = kNone;
    for (const int64_t q : s.pending)
      if (q != kDone && (border_[static_cast<std::size_t>(q)] & (1U << side))) {
        next = members_[static_cast<std::size_t>(q)];
        break;
      }
    if (next == kNone) {
      auto q = static_cast<std::size_t>(s.pos);
      const auto end = static_cast<std::size_t>(s.end);
      while (q < end && !(border_[q] & (1U << side))) ++q;
      if (q < end) next = members_[q];
    }
    // Release: the robot's cells are written before a neighbour reads that it is done.
    s.next_border[side].store(next, std::memory_order_release);
  }
  changed(s);
}

}  // namespace swarmcheck::impl::exploration
