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
  // The strip of each row (reusing row_count_), then the members strip by strip in index order.
  std::vector<int64_t>& start = start_;
  start.assign(static_cast<std::size_t>(count_) + 1, 0);
  for (int32_t k = 0; k < count_; ++k)
    for (int32_t i = lo_[static_cast<std::size_t>(k)]; i < lo_[static_cast<std::size_t>(k) + 1]; ++i) {
      start[static_cast<std::size_t>(k) + 1] += row_count_[static_cast<std::size_t>(i)];
      row_count_[static_cast<std::size_t>(i)] = k;
    }
  for (int32_t k = 0; k < count_; ++k) start[static_cast<std::size_t>(k) + 1] += start[static_cast<std::size_t>(k)];
  members_.resize(static_cast<std::size_t>(n));
  border_.resize(static_cast<std::size_t>(n));
  std::vector<int64_t>& fill = fill_;
  fill.assign(start.begin(), start.end() - 1);
  for (int32_t k = 0; k < count_; ++k)
    for (int side : {kLower, kUpper}) strips_[static_cast<std::size_t>(k)].first_border[side] = start[static_cast<std::size_t>(k) + 1];
  for (int64_t r = 0; r < n; ++r) {
    const int32_t i = rows[static_cast<std::size_t>(r)];
    const auto k = static_cast<std::size_t>(row_count_[static_cast<std::size_t>(i)]);
    const auto p = static_cast<std::size_t>(fill[k]++);
    members_[p] = static_cast<int32_t>(r);
    uint8_t b = 0;
    if (k > 0 && i - lo_[k] < reach) b |= 1U << kLower;                            // within reach of the strip below
    if (k + 1 < static_cast<std::size_t>(count_) && lo_[k + 1] - 1 - i < reach) b |= 1U << kUpper;   // or above
    border_[p] = b;
    for (int side : {kLower, kUpper})
      if ((b & (1U << side)) && strips_[k].first_border[side] == start[k + 1]) strips_[k].first_border[side] = static_cast<int64_t>(p);
  }
  for (int32_t k = 0; k < count_; ++k) {
    Strip& s = strips_[static_cast<std::size_t>(k)];
    s.begin = start[static_cast<std::size_t>(k)];
    s.end = start[static_cast<std::size_t>(k) + 1];
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
