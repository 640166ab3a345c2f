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
  count_ = cut_strips(cells, map_size, reach, strips, row_count_, lo_);
  if (count_ <= 1) return false;

  // Robots bucketed by row (a counting sort: index order within a row), each with its column, so
  // that the closure below scans contiguous memory; and each row's strip. Cursors and arrays are
  // held in locals: behind references, every byte store might alias them.
  row_start_.resize(static_cast<std::size_t>(map_size) + 1);
  row_start_[0] = 0;
  for (int32_t i = 0; i < map_size; ++i)
    row_start_[static_cast<std::size_t>(i) + 1] = row_start_[static_cast<std::size_t>(i)] + row_count_[static_cast<std::size_t>(i)];
  by_row_.resize(cells.size());
  by_row_column_.resize(cells.size());
  {
    int32_t* const cursor = row_count_.data();   // reused as the filling cursor
    std::copy(row_start_.begin(), row_start_.end() - 1, cursor);
    int32_t* const robot = by_row_.data();
    const int32_t* const row = rows_.data();
    for (int64_t r = 0; r < n; ++r) robot[cursor[row[r]]++] = static_cast<int32_t>(r);
    int32_t* const column = by_row_column_.data();
    for (int64_t p = 0; p < n; ++p) column[p] = cells[static_cast<std::size_t>(robot[p])][1];
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
      if (std::abs(by_row_column_[p] - c[1]) > reach) continue;   // most robots of the rows: no read of their own
      const int32_t r = by_row_[p];
      if (r <= t || is_deferred_[static_cast<std::size_t>(r)]) continue;
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
  fill_.assign(start_.begin(), start_.end() - 1);
  deferred_.clear();
  {
    int64_t* const cursor = fill_.data();
    int32_t* const members = members_.data();
    const uint8_t* const deferred = is_deferred_.data();
    const int32_t* const strip_of = strip_of_row_.data();
    const int32_t* const row = rows_.data();
    for (int64_t r = 0; r < n; ++r) {
      if (deferred[r]) {
        deferred_.push_back(static_cast<int32_t>(r));
        continue;
      }
      members[cursor[strip_of[row[r]]]++] = static_cast<int32_t>(r);
    }
  }
  return true;
}

}  // namespace swarmcheck::impl::exploration
