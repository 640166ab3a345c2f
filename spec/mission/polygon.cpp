// Polygon obstacles rasterised onto the occupancy grid (the rule is in polygon.hpp).
#include "spec/mission/polygon.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "spec/util/demand.hpp"

namespace swarmcheck::mission {

double polygon_area2(const std::vector<Point>& poly) {
  double out = 0.0;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const Point& a = poly[k];
    const Point& b = poly[(k + 1) % poly.size()];
    out += a[0] * b[1] - b[0] * a[1];
  }
  return out;
}

bool inside_polygon(const std::vector<Point>& poly, const Point& p) {
  bool in = false;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const Point& a = poly[k];
    const Point& b = poly[(k + 1) % poly.size()];
    if ((a[1] > p[1]) != (b[1] > p[1]) &&
        p[0] < a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))
      in = !in;
  }
  return in;
}

bool segment_meets_open_square(const Point& a, const Point& b, const Point& lo, const Point& hi) {
  double enter = -std::numeric_limits<double>::infinity();
  double leave = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < 2; ++k) {
    const double d = b[k] - a[k];
    if (d == 0.0) {
      if (!(lo[k] < a[k] && a[k] < hi[k])) return false;
      continue;
    }
    const double t0 = (lo[k] - a[k]) / d;
    const double t1 = (hi[k] - a[k]) / d;
    enter = std::max(enter, std::min(t0, t1));
    leave = std::min(leave, std::max(t0, t1));
  }
  return enter < leave && enter < 1.0 && leave > 0.0;
}

std::vector<char> polygon_cells(const GridWorld& w, const std::vector<Point>& poly) {
  SWARM_DEMAND(poly.size() >= 3);
  SWARM_DEMAND(w.rows > 0 && w.cols > 0);
  using Index = std::ptrdiff_t;
  const double res = w.resolution_m;
  Point lo = poly[0], hi = poly[0];
  for (const Point& p : poly)
    for (std::size_t k = 0; k < 2; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  // Columns and rows (counted from the bottom) the bounding box can touch, one cell of slack.
  const auto span = [&](double from, double to, double o, std::size_t n) {
    const Index a = std::max(Index{0}, static_cast<Index>(std::floor((from - o) / res)) - 1);
    const Index b = std::min(static_cast<Index>(n) - 1, static_cast<Index>(std::floor((to - o) / res)) + 1);
    return std::pair<Index, Index>{a, b};
  };
  std::vector<char> out(w.rows * w.cols, 0);
  const auto [j0, j1] = span(lo[0], hi[0], w.origin[0], w.cols);
  const auto [k0, k1] = span(lo[1], hi[1], w.origin[1], w.rows);
  for (Index k = k0; k <= k1; ++k)
    for (Index j = j0; j <= j1; ++j) {
      const Point c_lo{w.origin[0] + static_cast<double>(j) * res, w.origin[1] + static_cast<double>(k) * res};
      const Point c_hi{c_lo[0] + res, c_lo[1] + res};
      bool meets = inside_polygon(poly, {c_lo[0] + res / 2, c_lo[1] + res / 2});
      for (std::size_t e = 0; e < poly.size() && !meets; ++e)
        meets = segment_meets_open_square(poly[e], poly[(e + 1) % poly.size()], c_lo, c_hi);
      const auto i = static_cast<std::size_t>(static_cast<Index>(w.rows) - 1 - k);
      out[i * w.cols + static_cast<std::size_t>(j)] = meets ? 1 : 0;
    }
  return out;
}

}  // namespace swarmcheck::mission
