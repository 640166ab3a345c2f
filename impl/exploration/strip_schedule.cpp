#include "impl/exploration/strip_schedule.hpp"

#include <algorithm>

namespace swarmcheck::impl::exploration {

int32_t cut_strips(std::span<const int32_t> rows, int32_t map_rows, int32_t reach, int32_t strips,
                   std::vector<int32_t>& row_count, std::vector<int32_t>& lo) {
  const int64_t n = static_cast<int64_t>(rows.size());
  const int64_t min_height = int64_t{reach} + 1;
  // Strip boundaries at robot-count quantiles of the rows, each strip at least min_height rows.
  row_count.assign(static_cast<std::size_t>(map_rows), 0);
  for (int32_t i : rows) ++row_count[static_cast<std::size_t>(i)];
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

int32_t StripSchedule::build(std::span<const int32_t> rows, int32_t map_rows, int32_t reach, int32_t strips) {
  // The same rows as the last build (a step's deposit centres are, under most rules, the cells the
  // next step's robots decide from): its lists hold, only the strips' progress starts again.
  if (count_ > 0 && map_rows == built_for_.map_rows && reach == built_for_.reach && strips == built_for_.strips &&
      std::equal(rows.begin(), rows.end(), built_rows_.begin(), built_rows_.end())) {
    restart();
    return count_;
  }
  built_for_ = {map_rows, reach, strips};
  built_rows_.assign(rows.begin(), rows.end());
  const int64_t n = static_cast<int64_t>(rows.size());
  count_ = cut_strips(rows, map_rows, reach, strips, row_count_, lo_);
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
    const int32_t* const row = rows.data();
    for (int64_t r = 0; r < n; ++r) {
      const int32_t i = row[r];
      const int64_t p = cursor[strip_of[i]]++;
      members[p] = static_cast<int32_t>(r);
      border[p] = border_of[i];
    }
  }
  for (int32_t k = 0; k < count_; ++k) {
    Strip& s = strips_[static_cast<std::size_t>(k)];
    s.begin = start[static_cast<std::size_t>(k)];
    s.end = start[static_cast<std::size_t>(k) + 1];
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
    for (int side : {kLower, kUpper}) {
      const int64_t q = s.first_border[side];
      s.next_border[side].store(q < s.end ? members_[static_cast<std::size_t>(q)] : kNone, std::memory_order_relaxed);
    }
  }
}

}  // namespace swarmcheck::impl::exploration
