#include "impl/exploration/band_schedule.hpp"

#include <algorithm>
#include <cstdlib>

#include "impl/exploration/strip_schedule.hpp"

namespace swarmcheck::impl::exploration {

bool BandSchedule::build(std::span<const swarmcheck::exploration::CellIndex> cells, int32_t map_size, int32_t reach,
                         int32_t strips) {
  const auto n = static_cast<int64_t>(cells.size());
  const double side = 2.0 * reach + 1.0;
  if (static_cast<double>(n) * side * side > kMaxNeighbours * static_cast<double>(map_size) * map_size) return false;
  rows_.resize(cells.size());
  for (std::size_t r = 0; r < cells.size(); ++r) rows_[r] = cells[r][0];
  count_ = cut_strips(rows_, map_size, reach, strips, row_count_, lo_);
  if (count_ <= 1) return false;

  // Robots bucketed by row (a counting sort: index order within a row), and each row's strip.
  row_start_.assign(static_cast<std::size_t>(map_size) + 1, 0);
  for (int32_t i = 0; i < map_size; ++i)
    row_start_[static_cast<std::size_t>(i) + 1] = row_start_[static_cast<std::size_t>(i)] + row_count_[static_cast<std::size_t>(i)];
  by_row_.resize(cells.size());
  {
    std::vector<int32_t>& fill = row_count_;   // reused as the filling cursor
    std::copy(row_start_.begin(), row_start_.end() - 1, fill.begin());
    for (int64_t r = 0; r < n; ++r) by_row_[static_cast<std::size_t>(fill[static_cast<std::size_t>(rows_[static_cast<std::size_t>(r)])]++)] = static_cast<int32_t>(r);
  }
  strip_of_row_.resize(static_cast<std::size_t>(map_size));
  for (int32_t k = 0; k < count_; ++k)
    for (int32_t i = lo_[static_cast<std::size_t>(k)]; i < lo_[static_cast<std::size_t>(k) + 1]; ++i)
      strip_of_row_[static_cast<std::size_t>(i)] = k;

  // The border robots: within reach rows of a strip edge.
  is_deferred_.assign(cells.size(), 0);
  queue_.clear();
  for (int32_t k = 1; k < count_; ++k) {
    const int32_t edge = lo_[static_cast<std::size_t>(k)];   // the first row of strip k
    const int32_t i0 = std::max(0, edge - reach), i1 = std::min(map_size, edge + reach);
    for (auto p = static_cast<std::size_t>(row_start_[static_cast<std::size_t>(i0)]);
         p < static_cast<std::size_t>(row_start_[static_cast<std::size_t>(i1)]); ++p) {
      const int32_t r = by_row_[p];
      if (!is_deferred_[static_cast<std::size_t>(r)]) {
        is_deferred_[static_cast<std::size_t>(r)] = 1;
        queue_.push_back(r);
      }
    }
  }
  // The closure: a robot within reach of a deferred robot of smaller index is deferred too.
  const int64_t max_deferred = std::max<int64_t>(kMinDeferredCap, n / kMaxDeferredShare);
  for (std::size_t q = 0; q < queue_.size(); ++q) {
    if (static_cast<int64_t>(queue_.size()) > max_deferred) return false;
    const int32_t t = queue_[q];
    const auto& c = cells[static_cast<std::size_t>(t)];
    const int32_t i0 = std::max(0, c[0] - reach), i1 = std::min(map_size - 1, c[0] + reach);
    for (auto p = static_cast<std::size_t>(row_start_[static_cast<std::size_t>(i0)]);
         p < static_cast<std::size_t>(row_start_[static_cast<std::size_t>(i1) + 1]); ++p) {
      const int32_t r = by_row_[p];
      if (r <= t || is_deferred_[static_cast<std::size_t>(r)]) continue;
      if (std::abs(cells[static_cast<std::size_t>(r)][1] - c[1]) > reach) continue;
      is_deferred_[static_cast<std::size_t>(r)] = 1;
      queue_.push_back(r);
    }
  }
  if (static_cast<int64_t>(queue_.size()) > max_deferred) return false;

  // Phase 1's lists, strip by strip in index order; phase 2's in index order.
  // A strip's members: the robots of its rows (the row buckets say how many) but the deferred.
  start_.assign(static_cast<std::size_t>(count_) + 1, 0);
  for (int32_t k = 0; k < count_; ++k)
    start_[static_cast<std::size_t>(k) + 1] = row_start_[static_cast<std::size_t>(lo_[static_cast<std::size_t>(k) + 1])] -
                                              row_start_[static_cast<std::size_t>(lo_[static_cast<std::size_t>(k)])];
  for (int32_t t : queue_) --start_[static_cast<std::size_t>(strip_of_row_[static_cast<std::size_t>(rows_[static_cast<std::size_t>(t)])]) + 1];
  for (int32_t k = 0; k < count_; ++k) start_[static_cast<std::size_t>(k) + 1] += start_[static_cast<std::size_t>(k)];
  members_.resize(static_cast<std::size_t>(start_[static_cast<std::size_t>(count_)]));
  std::vector<int64_t>& fill = fill_;
  fill.assign(start_.begin(), start_.end() - 1);
  deferred_.clear();
  for (int64_t r = 0; r < n; ++r) {
    if (is_deferred_[static_cast<std::size_t>(r)]) {
      deferred_.push_back(static_cast<int32_t>(r));
      continue;
    }
    const auto k = static_cast<std::size_t>(strip_of_row_[static_cast<std::size_t>(rows_[static_cast<std::size_t>(r)])]);
    members_[static_cast<std::size_t>(fill[k]++)] = static_cast<int32_t>(r);
  }
  return true;
}

}  // namespace swarmcheck::impl::exploration
