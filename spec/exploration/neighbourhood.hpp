#pragma once
// The neighbourhood of a cell and the deposit around it (DESIGN.md A2, A4).
//
// The window of cell c is every in-map cell within Chebyshev distance s_range of c, scanned in
// raster order: i outer, j inner, both increasing (the thesis's loops). Candidates for a move
// are the window without c itself; the deposit covers the window including c.
#include <cmath>
#include <cstdint>

#include "spec/exploration/types.hpp"

namespace swarmcheck::exploration {

// The clipped window [i_lo, i_hi] x [j_lo, j_hi] (inclusive) around c.
struct Window {
  int32_t i_lo, i_hi, j_lo, j_hi;
};

inline Window window_around(CellIndex c, int32_t s_range, int32_t map_size) {
  auto lo = [&](int32_t v) { return v - s_range < 0 ? 0 : v - s_range; };
  auto hi = [&](int32_t v) { return v > map_size - 1 - s_range ? map_size - 1 : v + s_range; };
  return Window{lo(c[0]), hi(c[0]), lo(c[1]), hi(c[1])};
}

inline bool in_map(CellIndex c, int32_t map_size) {
  return c[0] >= 0 && c[1] >= 0 && c[0] < map_size && c[1] < map_size;
}

// The pheromone a robot leaves on a cell (di, dj) cells away from the deposit centre:
// deposit_amount_rule (deposit.hpp) at d, the Euclidean distance between the cell centres.
double deposit_amount(const Params& p, int32_t di, int32_t dj);

// The cell whose square contains a point (thesis findCellFromCoordinates, any cell size).
inline CellIndex cell_of(Point_m p, double cell_size_m) {
  return CellIndex{static_cast<int32_t>(std::floor(p[0] / cell_size_m)),
                   static_cast<int32_t>(std::floor(p[1] / cell_size_m))};
}

// The centre of a cell, the waypoint the Environment issues: ((i + 0.5) s, (j + 0.5) s).
inline Point_m centre_of(CellIndex c, double cell_size_m) {
  return Point_m{(c[0] + 0.5) * cell_size_m, (c[1] + 0.5) * cell_size_m};
}

// Exploration percentage: 100 * visited / free cells.
inline double exploration_percent(int64_t visited, int64_t free_cells) {
  return (static_cast<double>(visited) / static_cast<double>(free_cells)) * 100.0;
}

}  // namespace swarmcheck::exploration
