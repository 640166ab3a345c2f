#pragma once
// The neighbourhood of a cell and the deposit around it (DESIGN.md A2, A4).
//
// The window of cell c is every in-map cell within Chebyshev distance s_range of c, scanned in
// raster order: i outer, j inner, both increasing (the thesis's loops). Candidates for a move
// are the window without c itself; the deposit covers the window including c.
//
// window_around is written once over a domain D (spec/util/num.hpp): the concrete code clips
// the window to the map; a proof interprets the same rule for a symbolic cell of a symbolic map.
#include <array>
#include <cmath>
#include <cstdint>

#include "spec/exploration/types.hpp"
#include "spec/util/num.hpp"

namespace swarmcheck::exploration {

// A cell in domain D: CellIndex for num::Concrete.
template <class D>
using CellOf = std::array<typename D::Int, 2>;

// The clipped window [i_lo, i_hi] x [j_lo, j_hi] (inclusive) around c.
template <class D>
struct WindowT {
  typename D::Int i_lo, i_hi, j_lo, j_hi;
};
using Window = WindowT<num::Concrete>;

// The window of c: s_range cells each way, clipped to the map (neighbourhood.cpp instantiates it
// for both domains).
template <class D>
WindowT<D> window_around_rule(const CellOf<D>& c, int32_t s_range, const typename D::Int& map_size);

inline Window window_around(CellIndex c, int32_t s_range, int32_t map_size) {
  return window_around_rule<num::Concrete>(c, s_range, map_size);
}
inline WindowT<num::Symbolic> window_around(const CellOf<num::Symbolic>& c, int32_t s_range, const sym::Int& map_size) {
  return window_around_rule<num::Symbolic>(c, s_range, map_size);
}

// Visits the cells of window w around c in raster order: f(cell, in_window, di, dj), (di, dj)
// the cell's offset from c. The concrete loop runs over the clipped window, every cell in it; a
// symbolic window's bounds are expressions, so the symbolic loop runs over every offset of
// [-s_range, s_range]^2 in the same order, a cell in the window when the bounds hold. The two
// visit the same cells in the same order (tests/exploration holds them to it).
template <class F>
void for_each_window_cell(const Window& w, CellIndex c, int32_t /*s_range*/, F&& f) {
  for (int32_t i = w.i_lo; i <= w.i_hi; ++i)
    for (int32_t j = w.j_lo; j <= w.j_hi; ++j) f(CellIndex{i, j}, true, i - c[0], j - c[1]);
}
template <class F>
void for_each_window_cell(const WindowT<num::Symbolic>& w, const CellOf<num::Symbolic>& c, int32_t s_range, F&& f) {
  for (int32_t di = -s_range; di <= s_range; ++di)
    for (int32_t dj = -s_range; dj <= s_range; ++dj) {
      const CellOf<num::Symbolic> cell{c[0] + di, c[1] + dj};
      const sym::Bool in = w.i_lo <= cell[0] && cell[0] <= w.i_hi && w.j_lo <= cell[1] && cell[1] <= w.j_hi;
      f(cell, in, di, dj);
    }
}

template <class D>
typename D::Bool in_map_rule(const CellOf<D>& c, const typename D::Int& map_size) {
  return c[0] >= 0 && c[1] >= 0 && c[0] < map_size && c[1] < map_size;
}
inline bool in_map(CellIndex c, int32_t map_size) { return in_map_rule<num::Concrete>(c, map_size); }

// The pheromone a robot leaves on a cell (di, dj) cells away from the deposit centre:
// deposit_amount_rule (deposit.hpp) at d, the Euclidean distance between the cell centres.
double deposit_amount(const Params& p, int32_t di, int32_t dj);

// The cell whose square contains a point (thesis findCellFromCoordinates, any cell size).
inline CellIndex cell_of(Point_m p, double cell_size_m) {
  return CellIndex{static_cast<int32_t>(std::floor(p[0] / cell_size_m)),
                   static_cast<int32_t>(std::floor(p[1] / cell_size_m))};
}

// The centre of a cell, the waypoint the Environment issues: ((i + 0.5) s, (j + 0.5) s).
template <class D>
std::array<typename D::Real, 2> centre_of_rule(const CellOf<D>& c, const typename D::Real& cell_size_m) {
  return {(num::to_real(c[0]) + 0.5) * cell_size_m, (num::to_real(c[1]) + 0.5) * cell_size_m};
}
inline Point_m centre_of(CellIndex c, double cell_size_m) { return centre_of_rule<num::Concrete>(c, cell_size_m); }

// Exploration percentage: 100 * visited / free cells.
inline double exploration_percent(int64_t visited, int64_t free_cells) {
  return (static_cast<double>(visited) / static_cast<double>(free_cells)) * 100.0;
}

}  // namespace swarmcheck::exploration
