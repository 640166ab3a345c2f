#include "spec/exploration/reachability.hpp"

#include <vector>

#include "spec/exploration/neighbourhood.hpp"
#include "spec/exploration/scenario.hpp"

namespace swarmcheck::exploration {

Reachability reachability(const Scenario& s) {
  const int32_t n = s.map_size;
  const int32_t r = s.params.s_range;
  const auto index = [n](CellIndex c) { return static_cast<std::size_t>(int64_t{c[0]} * n + c[1]); };
  // seen: an obstacle, or a free cell already queued; one bit per cell.
  std::vector<bool> seen(static_cast<std::size_t>(int64_t{n} * n), false);
  for (const CellIndex& o : s.obstacles) seen[index(o)] = true;
  std::vector<CellIndex> queue;
  for (const Point_m& p : s.robots) {
    const CellIndex c = cell_of(p, s.cell_size);
    if (!seen[index(c)]) {
      seen[index(c)] = true;
      queue.push_back(c);
    }
  }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const Window w = window_around(queue[head], r, n);
    for (int32_t i = w.i_lo; i <= w.i_hi; ++i)
      for (int32_t j = w.j_lo; j <= w.j_hi; ++j) {
        const std::size_t k = static_cast<std::size_t>(int64_t{i} * n + j);
        if (seen[k]) continue;
        seen[k] = true;
        queue.push_back(CellIndex{i, j});
      }
  }
  Reachability out;
  out.reachable_free_cells = static_cast<int64_t>(queue.size());
  out.unreachable_free_cells = free_cell_count(s) - out.reachable_free_cells;
  return out;
}

}  // namespace swarmcheck::exploration
