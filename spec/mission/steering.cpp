// Local steering around robots, VFH-style: the binary polar histogram and its candidates.
#include "spec/mission/steering.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "spec/mission/separation.hpp"
#include "spec/mission/world.hpp"
#include "spec/util/demand.hpp"

namespace swarmcheck::mission {

namespace {

double point_square_distance(const Point& p, const Point& lo, const Point& hi) {
  const double dx = std::max({lo[0] - p[0], 0.0, p[0] - hi[0]});
  const double dy = std::max({lo[1] - p[1], 0.0, p[1] - hi[1]});
  return std::sqrt(dx * dx + dy * dy);
}

// Liang-Barsky: the segment [a, b] meets the closed square [lo, hi].
bool segment_meets_square(const Point& a, const Point& b, const Point& lo, const Point& hi) {
  double t0 = 0.0, t1 = 1.0;
  for (std::size_t k = 0; k < 2; ++k) {
    const double d = b[k] - a[k];
    if (d == 0.0) {
      if (a[k] < lo[k] || a[k] > hi[k]) return false;
      continue;
    }
    double enter = (lo[k] - a[k]) / d, leave = (hi[k] - a[k]) / d;
    if (enter > leave) std::swap(enter, leave);
    t0 = std::max(t0, enter);
    t1 = std::min(t1, leave);
    if (t0 > t1) return false;
  }
  return true;
}

// Sector k's segment is clear of the robot's map (see the header), in a world.
bool clear_of_map(const GridWorld& w, const std::vector<char>& map, const std::vector<char>& trav,
                  const Point& p, const Point& e, double radius_m) {
  const double keep = radius_m + kSteerPad_m;
  if (leaves_grid(w, e, keep)) return false;
  const auto end_cell = cell_of(w, e);
  if (!end_cell || !trav[*end_cell]) return false;
  const double res = w.resolution_m;
  const auto column = [&](double x) { return std::floor((x - w.origin[0]) / res); };
  const auto row_up = [&](double y) { return std::floor((y - w.origin[1]) / res); };  // from the bottom
  const double cols = static_cast<double>(w.cols), rows = static_cast<double>(w.rows);
  const double j0 = std::max(0.0, column(std::min(p[0], e[0]) - keep) - 1);
  const double j1 = std::min(cols - 1, column(std::max(p[0], e[0]) + keep) + 1);
  const double k0 = std::max(0.0, row_up(std::min(p[1], e[1]) - keep) - 1);
  const double k1 = std::min(rows - 1, row_up(std::max(p[1], e[1]) + keep) + 1);
  for (double k = k0; k <= k1; ++k)
    for (double j = j0; j <= j1; ++j) {
      const auto cell = static_cast<std::size_t>(rows - 1 - k) * w.cols + static_cast<std::size_t>(j);
      if (!map[cell]) continue;
      const Point lo{w.origin[0] + j * res, w.origin[1] + k * res};
      const Point hi{lo[0] + res, lo[1] + res};
      if (segment_square_distance(p, e, lo, hi) < keep) return false;
    }
  return true;
}

}  // namespace

bool standoff(std::size_t i, std::size_t j, std::span<const RobotWay> ways) {
  SWARM_DEMAND(i < ways.size() && j < ways.size());
  std::size_t k = j;
  for (std::size_t hops = 0; hops < ways.size(); ++hops) {
    if (!ways[k].yielded_to) return false;    // it moved, or is parked
    if (k > i && !ways[k].stuck) return false;  // it only waited, in the step before
    if (*ways[k].yielded_to == i) return true;
    k = *ways[k].yielded_to;
  }
  return false;  // the others wait for each other, not for i

}

double segment_square_distance(const Point& a, const Point& b, const Point& lo, const Point& hi) {
  if (segment_meets_square(a, b, lo, hi)) return 0.0;
  double out = std::min(point_square_distance(a, lo, hi), point_square_distance(b, lo, hi));
  for (const Point& corner : {lo, Point{hi[0], lo[1]}, hi, Point{lo[0], hi[1]}})
    out = std::min(out, distance_to_segment(corner, a, b));
  return out;
}

std::vector<Point> steer_candidates(const Mission& m, std::size_t i, const Point& at,
                                    const Point& waypoint, const SteerView& view) {
  SWARM_DEMAND(view.positions.size() == m.robots.size());
  SWARM_DEMAND(!m.world || (view.map && view.traversable));
  const double radius = m.robots[i].radius;
  // The bearing in sectors: the angular distances of the sectors are then exact for a bearing
  // on a sector (ties between the two sides break by sector index, as the header says).
  const double sectors = static_cast<double>(kSteerSectors);
  const double bearing =
      std::atan2(waypoint[1] - at[1], waypoint[0] - at[0]) * sectors / (2.0 * std::numbers::pi);
  std::vector<std::pair<double, Point>> free;  // (angular distance, detour point), by sector
  for (std::size_t k = 0; k < kSteerSectors; ++k) {
    const double a = 2.0 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(kSteerSectors);
    const double off = std::abs(std::remainder(static_cast<double>(k) - bearing, sectors));
    if (off > sectors * (100.0 / 360.0)) continue;  // within 100 degrees
    const Point e{at[0] + kSteerLookahead_m * std::cos(a), at[1] + kSteerLookahead_m * std::sin(a)};
    bool clear = true;
    for (std::size_t j = 0; j < view.positions.size() && clear; ++j) {
      if (j == i) continue;
      const Point& q = view.positions[j];
      clear = distance_to_segment(q, at, e) >= radius + m.robots[j].radius;
    }
    if (clear && m.world) clear = clear_of_map(*m.world, *view.map, *view.traversable, at, e, radius);
    if (clear) free.emplace_back(off, e);
  }
  // By angular distance; the sectors were added in index order, which breaks ties.
  std::stable_sort(free.begin(), free.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<Point> out;
  out.reserve(free.size());
  for (const auto& f : free) out.push_back(f.second);
  return out;
}

}  // namespace swarmcheck::mission
