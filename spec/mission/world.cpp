// The world of a mission: the occupancy grid's geometry, A* on it, and the world's checks.
#include "spec/mission/world.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <set>
#include <utility>

#include "spec/mission/polygon.hpp"
#include "spec/mission/sensing.hpp"
#include "spec/util/input_error.hpp"

namespace swarmcheck::mission {

namespace {

using Index = std::ptrdiff_t;

Index rows_of(const GridWorld& w) { return static_cast<Index>(w.rows); }
Index cols_of(const GridWorld& w) { return static_cast<Index>(w.cols); }
std::size_t at(const GridWorld& w, Index i, Index j) {
  return static_cast<std::size_t>(i * cols_of(w) + j);
}

// Lower-left corner of cell (i, j), row i from the top.
Point lower_left(const GridWorld& w, Index i, Index j) {
  return {w.origin[0] + static_cast<double>(j) * w.resolution_m,
          w.origin[1] + static_cast<double>(rows_of(w) - 1 - i) * w.resolution_m};
}

std::string point_text(const Point& p) { return fmt::format("[{}, {}]", p[0], p[1]); }

// The A* search of the header over cells; goal marks the goal cells, [lo, hi] their bounding box
// (rows, columns) for the octile heuristic. The cells from start to a goal, or nothing.
std::optional<std::vector<std::size_t>> astar(const GridWorld& w, const std::vector<char>& trav,
                                              std::size_t start, const std::vector<char>& goal,
                                              std::array<Index, 2> lo, std::array<Index, 2> hi) {
  const double res = w.resolution_m;
  const double diag = res * std::sqrt(2.0);
  const auto h = [&](Index i, Index j) {
    const Index di = std::max({lo[0] - i, Index{0}, i - hi[0]});
    const Index dj = std::max({lo[1] - j, Index{0}, j - hi[1]});
    const Index straight = std::max(di, dj) - std::min(di, dj);
    return static_cast<double>(straight) * res + static_cast<double>(std::min(di, dj)) * diag;
  };
  const std::size_t n = w.rows * w.cols;
  std::vector<double> g(n, std::numeric_limits<double>::infinity());
  std::vector<std::size_t> parent(n, n);
  std::vector<char> closed(n, 0);
  using Open = std::pair<double, std::size_t>;  // f, cell: least f, then least index
  std::priority_queue<Open, std::vector<Open>, std::greater<>> open;
  const auto free_at = [&](Index i, Index j) {
    return i >= 0 && j >= 0 && i < rows_of(w) && j < cols_of(w) && trav[at(w, i, j)] != 0;
  };
  g[start] = 0.0;
  open.emplace(h(static_cast<Index>(start) / cols_of(w), static_cast<Index>(start) % cols_of(w)),
               start);
  while (!open.empty()) {
    const std::size_t c = open.top().second;
    open.pop();
    if (closed[c]) continue;
    closed[c] = 1;
    if (goal[c]) {
      std::vector<std::size_t> path;
      for (std::size_t k = c; k != n; k = parent[k]) path.push_back(k);
      std::reverse(path.begin(), path.end());
      return path;
    }
    const Index i = static_cast<Index>(c) / cols_of(w);
    const Index j = static_cast<Index>(c) % cols_of(w);
    for (Index di = -1; di <= 1; ++di)
      for (Index dj = -1; dj <= 1; ++dj) {
        if ((di == 0 && dj == 0) || !free_at(i + di, j + dj)) continue;
        const bool diagonal = di != 0 && dj != 0;
        if (diagonal && !(free_at(i + di, j) && free_at(i, j + dj))) continue;  // no corner cut
        const std::size_t next = at(w, i + di, j + dj);
        const double ng = g[c] + (diagonal ? diag : res);
        if (ng < g[next]) {
          g[next] = ng;
          parent[next] = c;
          open.emplace(ng + h(i + di, j + dj), next);
        }
      }
  }
  return std::nullopt;
}

// Waypoints: the centres of the cells where the path turns, then `last`.
Route route_along(const GridWorld& w, const std::vector<std::size_t>& cells, const Point& from,
                  const Point& last) {
  Route out;
  const auto step = [&](std::size_t k) {
    const Index a = static_cast<Index>(cells[k - 1]), b = static_cast<Index>(cells[k]);
    return std::make_pair(b / cols_of(w) - a / cols_of(w), b % cols_of(w) - a % cols_of(w));
  };
  for (std::size_t k = 1; k + 1 < cells.size(); ++k)
    if (step(k) != step(k + 1)) out.waypoints.push_back(cell_centre(w, cells[k]));
  out.waypoints.push_back(last);
  Point prev = from;
  for (const auto& p : out.waypoints) {
    out.length_m += distance(prev, p);
    prev = p;
  }
  return out;
}

}  // namespace

std::optional<std::size_t> cell_of(const GridWorld& w, const Point& p) {
  const double fx = (p[0] - w.origin[0]) / w.resolution_m;
  const double fy = (p[1] - w.origin[1]) / w.resolution_m;
  if (!(fx >= 0.0 && fy >= 0.0 && fx <= static_cast<double>(w.cols) &&
        fy <= static_cast<double>(w.rows)))
    return std::nullopt;
  const Index j = std::min(static_cast<Index>(std::floor(fx)), cols_of(w) - 1);
  const Index k = std::min(static_cast<Index>(std::floor(fy)), rows_of(w) - 1);
  return at(w, rows_of(w) - 1 - k, j);
}

Point cell_centre(const GridWorld& w, std::size_t cell) {
  const Point ll = lower_left(w, static_cast<Index>(cell / w.cols), static_cast<Index>(cell % w.cols));
  return {ll[0] + w.resolution_m / 2, ll[1] + w.resolution_m / 2};
}

bool leaves_grid(const GridWorld& w, const Point& p, double radius_m) {
  const double res = w.resolution_m;
  return p[0] - radius_m < w.origin[0] || p[1] - radius_m < w.origin[1] ||
         p[0] + radius_m > w.origin[0] + static_cast<double>(w.cols) * res ||
         p[1] + radius_m > w.origin[1] + static_cast<double>(w.rows) * res;
}

bool overlaps_obstacle(const GridWorld& w, const Point& p, double radius_m) {
  return leaves_grid(w, p, radius_m) || !overlapped_cells(w, p, radius_m).empty();
}

std::vector<std::size_t> overlapped_cells(const GridWorld& w, const Point& p, double radius_m) {
  const double res = w.resolution_m;
  const auto index = [&](double v, double o) { return static_cast<Index>(std::floor((v - o) / res)); };
  const Index j0 = std::max(Index{0}, index(p[0] - radius_m, w.origin[0]) - 1);
  const Index j1 = std::min(cols_of(w) - 1, index(p[0] + radius_m, w.origin[0]) + 1);
  const Index k0 = std::max(Index{0}, index(p[1] - radius_m, w.origin[1]) - 1);
  const Index k1 = std::min(rows_of(w) - 1, index(p[1] + radius_m, w.origin[1]) + 1);
  std::vector<std::size_t> out;
  for (Index k = k0; k <= k1; ++k)
    for (Index j = j0; j <= j1; ++j) {
      const Index i = rows_of(w) - 1 - k;
      if (!w.occupied[at(w, i, j)]) continue;
      const Point lo = lower_left(w, i, j);
      const Point hi{lo[0] + res, lo[1] + res};
      const double dx = std::max({lo[0] - p[0], 0.0, p[0] - hi[0]});
      const double dy = std::max({lo[1] - p[1], 0.0, p[1] - hi[1]});
      if (dx * dx + dy * dy < radius_m * radius_m ||
          (lo[0] < p[0] && p[0] < hi[0] && lo[1] < p[1] && p[1] < hi[1]))
        out.push_back(at(w, i, j));
    }
  return out;
}

double traversable_checks(const GridWorld& w, double radius_m) {
  const double reach = std::ceil((radius_m + w.resolution_m / 2) / w.resolution_m) + 1;
  return static_cast<double>(w.rows * w.cols) * (2 * reach + 1) * (2 * reach + 1);
}

std::vector<char> traversable_cells(const GridWorld& w, double radius_m) {
  const double res = w.resolution_m;
  const double need = radius_m + res / 2;  // clearance of the cell's square
  const Index reach = static_cast<Index>(std::ceil(need / res)) + 1;
  std::vector<char> out(w.rows * w.cols, 0);
  for (Index i = 0; i < rows_of(w); ++i)
    for (Index j = 0; j < cols_of(w); ++j) {
      if (w.occupied[at(w, i, j)]) continue;
      const Index border = std::min({i, rows_of(w) - 1 - i, j, cols_of(w) - 1 - j});
      if (static_cast<double>(border) * res < need) continue;
      bool clear = true;
      for (Index di = -reach; di <= reach && clear; ++di)
        for (Index dj = -reach; dj <= reach && clear; ++dj) {
          const Index a = i + di, b = j + dj;
          if (a < 0 || b < 0 || a >= rows_of(w) || b >= cols_of(w) || !w.occupied[at(w, a, b)])
            continue;
          const double gx = static_cast<double>(std::max(Index{0}, std::abs(dj) - 1)) * res;
          const double gy = static_cast<double>(std::max(Index{0}, std::abs(di) - 1)) * res;
          clear = gx * gx + gy * gy >= need * need;
        }
      out[at(w, i, j)] = clear ? 1 : 0;
    }
  return out;
}

std::optional<Route> route_to_point(const GridWorld& w, const std::vector<char>& traversable,
                                    const Point& from, const Point& to) {
  const auto s = cell_of(w, from);
  const auto t = cell_of(w, to);
  if (!s || !t || (*t != *s && !traversable[*t])) return std::nullopt;
  std::vector<char> goal(w.rows * w.cols, 0);
  goal[*t] = 1;
  const Index ti = static_cast<Index>(*t / w.cols), tj = static_cast<Index>(*t % w.cols);
  const auto cells = astar(w, traversable, *s, goal, {ti, tj}, {ti, tj});
  if (!cells) return std::nullopt;
  return route_along(w, *cells, from, to);
}

std::optional<Route> route_to_region(const GridWorld& w, const std::vector<char>& traversable,
                                     const Point& from, const Region& region) {
  const auto s = cell_of(w, from);
  if (!s) return std::nullopt;
  std::vector<char> goal(w.rows * w.cols, 0);
  std::array<Index, 2> lo{rows_of(w), cols_of(w)}, hi{-1, -1};
  for (std::size_t c = 0; c < goal.size(); ++c)
    if ((c == *s || traversable[c]) && inside(region, cell_centre(w, c))) {
      goal[c] = 1;
      const Index i = static_cast<Index>(c / w.cols), j = static_cast<Index>(c % w.cols);
      lo = {std::min(lo[0], i), std::min(lo[1], j)};
      hi = {std::max(hi[0], i), std::max(hi[1], j)};
    }
  if (hi[0] < 0) return std::nullopt;
  const auto cells = astar(w, traversable, *s, goal, lo, hi);
  if (!cells) return std::nullopt;
  return route_along(w, *cells, from, cell_centre(w, cells->back()));
}

double travel_cost(const Mission& m, std::size_t robot, const Point& from, const Point& to) {
  if (!m.world) return distance(from, to);
  const auto r = route_to_point(*m.world, m.world->traversable[robot], from, to);
  return r ? r->length_m : std::numeric_limits<double>::infinity();
}

namespace {

// The grid of "rows" (checked), or nothing when the file gives size_m instead.
GridWorld grid_of_rows(const std::vector<std::string>& rows) {
  if (rows.empty() || rows[0].empty())
    throw InputError("world.rows", "expected at least one row of at least one cell");
  GridWorld w;
  w.rows = rows.size();
  w.cols = rows[0].size();
  if (w.rows * w.cols > kMaxWorldCells)
    throw InputError("world.rows", fmt::format("expected at most {} cells; got {} x {}",
                                               kMaxWorldCells, w.rows, w.cols));
  for (std::size_t i = 0; i < w.rows; ++i) {
    const std::string& row = rows[i];
    const auto bad = row.find_first_not_of(".#");
    if (row.size() != w.cols || bad != std::string::npos)
      throw InputError(fmt::format("world.rows[{}]", i),
                       fmt::format("expected {} characters (as rows[0]), each '.' (free) or '#' "
                                   "(occupied); got {} characters{}",
                                   w.cols, row.size(),
                                   bad == std::string::npos
                                       ? std::string()
                                       : fmt::format(", '{}' at column {}", row[bad], bad)));
    for (const char c : row) w.occupied.push_back(c == '#' ? 1 : 0);
  }
  return w;
}

// A free grid of ceil(width / res) x ceil(height / res) cells (columns x rows).
GridWorld grid_of_size(const Point& size_m, double res) {
  const double cols = std::ceil(size_m[0] / res), rows = std::ceil(size_m[1] / res);
  if (!(size_m[0] > 0.0 && size_m[1] > 0.0) || !std::isfinite(cols) || !std::isfinite(rows) ||
      cols * rows > static_cast<double>(kMaxWorldCells))
    throw InputError("world.size_m",
                     fmt::format("expected [width, height] in metres, both > 0, of at most {} cells "
                                 "of {} m; got [{}, {}]",
                                 kMaxWorldCells, res, size_m[0], size_m[1]));
  GridWorld w;
  w.rows = static_cast<std::size_t>(rows);
  w.cols = static_cast<std::size_t>(cols);
  w.occupied.assign(w.rows * w.cols, 0);
  return w;
}

// Every point on the line through the first point and the first point apart from it.
bool collinear(const std::vector<Point>& poly) {
  const Point& a = poly[0];
  const auto other = std::find_if(poly.begin(), poly.end(), [&](const Point& p) { return p != a; });
  if (other == poly.end()) return true;
  const Point& b = *other;
  return std::all_of(poly.begin(), poly.end(), [&](const Point& p) {
    return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) == 0.0;
  });
}

// Rasterises the polygons of `list` ("obstacles" or "unknown_obstacles") onto `cells`.
void add_polygons(const GridWorld& w, const std::vector<ObstacleDecl>& obstacles, const char* list,
                  std::vector<char>& cells_out, std::vector<std::vector<Point>>& polygons_out) {
  for (std::size_t k = 0; k < obstacles.size(); ++k) {
    const auto& poly = obstacles[k].polygon;
    const std::string path = fmt::format("world.{}[{}].polygon", list, k);
    if (poly.size() < 3)
      throw InputError(path, fmt::format("expected a polygon of at least 3 points [x, y]; got {}",
                                         poly.size()));
    if (polygon_area2(poly) == 0.0)
      throw InputError(path, collinear(poly) ? "expected a polygon of non-zero area; its points are on one line"
                                             : "expected a polygon of non-zero area; its outline crosses itself so "
                                               "that its parts cancel out (list the corners in order around it)");
    const std::vector<char> cells = polygon_cells(w, poly);
    for (std::size_t c = 0; c < cells.size(); ++c) cells_out[c] = cells_out[c] || cells[c];
    polygons_out.push_back(poly);
  }
}

void set_sensor(GridWorld& w, const SensorDecl& s) {
  if (s.beams < 1 || s.beams > 4096)
    throw InputError("world.sensor.beams", fmt::format("expected 1 to 4096 beams; got {}", s.beams));
  if (!std::isfinite(s.range_m) || s.range_m <= 0.0 || s.range_m > 1000.0)
    throw InputError("world.sensor.range_m",
                     fmt::format("expected a range in metres, > 0 and at most 1000; got {}", s.range_m));
  if (!std::isfinite(s.noise_m) || s.noise_m < 0.0 || s.noise_m > s.range_m)
    throw InputError("world.sensor.noise_m",
                     fmt::format("expected a standard deviation in metres, >= 0 and at most the "
                                 "range; got {}", s.noise_m));
  // A scan samples each beam every resolution / 8 out to the range or the world's edge: 4 096
  // beams of 1 000 m over a 250 m world in cells of 0.25 m were 46 M samples a robot a step (a
  // run went on for minutes). Bounded, with what to change.
  const double reach = std::min(s.range_m, std::hypot(static_cast<double>(w.cols), static_cast<double>(w.rows)) * w.resolution_m);
  const double samples = static_cast<double>(s.beams) * std::floor(reach / (w.resolution_m / 8));
  if (samples > kMaxScanSamples)
    throw InputError("world.sensor",
                     fmt::format("{} beams reaching {:.4g} m in cells of {} m take {:.3g} samples a scan (each robot, each "
                                 "step); at most {:.3g}: fewer beams, a shorter range or larger cells",
                                 s.beams, reach, w.resolution_m, samples, kMaxScanSamples));
  w.sensor_beams = s.beams;
  w.sensor_range_m = s.range_m;
  w.sensor_noise_m = s.noise_m;
}

}  // namespace

GridWorld build_world(const WorldDecl& d) {
  if (!std::isfinite(d.resolution_m) || d.resolution_m <= 0.0 || d.resolution_m > 1e6)
    throw InputError("world.resolution_m",
                     fmt::format("expected a cell side in metres, > 0 and at most 1e6; got {}",
                                 d.resolution_m));
  if (d.rows && d.size_m)
    throw InputError("world.size_m", "expected either \"rows\" or \"size_m\", not both");
  if (!d.rows && !d.size_m)
    throw InputError("world.rows", "missing (the grid's rows, top first: '#' occupied, '.' free; "
                                   "or world.size_m, [width, height] in metres of a free grid)");
  GridWorld w = d.rows ? grid_of_rows(*d.rows) : grid_of_size(*d.size_m, d.resolution_m);
  w.resolution_m = d.resolution_m;
  w.origin = d.origin;
  if (d.obstacles) add_polygons(w, *d.obstacles, "obstacles", w.occupied, w.polygons);
  if (d.unknown_obstacles) {
    w.hidden.assign(w.occupied.size(), 0);
    add_polygons(w, *d.unknown_obstacles, "unknown_obstacles", w.hidden, w.unknown_polygons);
    for (std::size_t c = 0; c < w.hidden.size(); ++c) w.hidden[c] = w.hidden[c] && !w.occupied[c];
  }
  if (d.sensor) set_sensor(w, *d.sensor);
  return w;
}

namespace {

// A polygon obstacle covering a robot's start or a task it may start: the message names the
// polygon's JSON path (the generic checks of check_world would only name the point's).
void check_polygons_clear(const Mission& m, const std::vector<std::set<std::size_t>>& tasks) {
  const GridWorld& w = *m.world;
  for (std::size_t k = 0; k < w.polygons.size(); ++k) {
    GridWorld only;
    only.resolution_m = w.resolution_m;
    only.origin = w.origin;
    only.rows = w.rows;
    only.cols = w.cols;
    only.occupied = polygon_cells(w, w.polygons[k]);
    const auto covers = [&](const Point& p, double radius) {
      return !leaves_grid(w, p, radius) && overlaps_obstacle(only, p, radius);
    };
    const std::string path = fmt::format("world.obstacles[{}].polygon", k);
    for (std::size_t r = 0; r < m.robots.size(); ++r) {
      const Robot& robot = m.robots[r];
      if (covers(robot.start, robot.radius))
        throw InputError(path, fmt::format("the polygon's cells cover the start {} of robot {} "
                                           "(radius {} m), robots[{}].start",
                                           point_text(robot.start), robot.name, robot.radius, r));
      for (const std::size_t t : tasks[r])
        if (covers(m.tasks[t].at, robot.radius))
          throw InputError(path, fmt::format("the polygon's cells cover task {} at {} (tasks[{}].at) "
                                             "for robot {} (radius {} m)",
                                             m.tasks[t].name, point_text(m.tasks[t].at), t,
                                             robot.name, robot.radius));
    }
  }
}

// Starts and tasks must be clear of the unknown obstacles too (nothing could complete there).
void check_clear_of_unknown(const Mission& m, const std::vector<std::set<std::size_t>>& tasks) {
  const GridWorld truth = true_world(*m.world);
  for (std::size_t r = 0; r < m.robots.size(); ++r) {
    const Robot& robot = m.robots[r];
    if (overlaps_obstacle(truth, robot.start, robot.radius))
      throw InputError(fmt::format("robots[{}].start", r),
                       fmt::format("robot {} (radius {} m) at {} overlaps an unknown obstacle",
                                   robot.name, robot.radius, point_text(robot.start)));
    for (const std::size_t t : tasks[r])
      if (overlaps_obstacle(truth, m.tasks[t].at, robot.radius))
        throw InputError(fmt::format("tasks[{}].at", t),
                         fmt::format("an unknown obstacle covers task {} at {} for robot {} "
                                     "(radius {} m)", m.tasks[t].name, point_text(m.tasks[t].at),
                                     robot.name, robot.radius));
  }
}

}  // namespace

void check_world(const Mission& m) {
  if (!m.world) return;
  const GridWorld& w = *m.world;
  // Per robot, the tasks and regions its events name.
  std::vector<std::set<std::size_t>> tasks(m.robots.size()), regions(m.robots.size());
  for (const auto& [name, mn] : m.events)
    (mn.kind == MeaningKind::task_start ? tasks : regions)[mn.robot].insert(mn.target);
  check_polygons_clear(m, tasks);
  if (!w.hidden.empty()) check_clear_of_unknown(m, tasks);
  for (std::size_t r = 0; r < m.robots.size(); ++r)
    if (overlaps_obstacle(w, m.robots[r].start, m.robots[r].radius))
      throw InputError(fmt::format("robots[{}].start", r),
                       fmt::format("robot {} (radius {} m) at {} overlaps an obstacle of the world "
                                   "or leaves its grid",
                                   m.robots[r].name, m.robots[r].radius,
                                   point_text(m.robots[r].start)));
  for (std::size_t t = 0; t < m.tasks.size(); ++t)
    for (std::size_t r = 0; r < m.robots.size(); ++r)
      if (tasks[r].count(t) && overlaps_obstacle(w, m.tasks[t].at, m.robots[r].radius))
        throw InputError(fmt::format("tasks[{}].at", t),
                         fmt::format("an obstacle of the world covers task {} at {} for robot {} "
                                     "(radius {} m), or the task is outside the grid",
                                     m.tasks[t].name, point_text(m.tasks[t].at),
                                     m.robots[r].name, m.robots[r].radius));
  const char* why = "no path of cells clear of the walls by its radius plus half a cell leads there";
  for (std::size_t r = 0; r < m.robots.size(); ++r) {
    const Robot& robot = m.robots[r];
    const auto& trav = w.traversable[r];
    for (const std::size_t t : tasks[r]) {
      if (!route_to_point(w, trav, robot.start, m.tasks[t].at))
        throw InputError(fmt::format("tasks[{}].at", t),
                         fmt::format("task {} at {} is unreachable for robot {} (radius {} m) from "
                                     "its start {}: {}",
                                     m.tasks[t].name, point_text(m.tasks[t].at), robot.name,
                                     robot.radius, point_text(robot.start), why));
    }
    for (const std::size_t t : tasks[r]) {
      for (const std::size_t u : tasks[r])
        if (u != t && !route_to_point(w, trav, m.tasks[u].at, m.tasks[t].at))
          throw InputError(fmt::format("tasks[{}].at", t),
                           fmt::format("task {} is unreachable for robot {} (radius {} m) from "
                                       "task {}: {}",
                                       m.tasks[t].name, robot.name, robot.radius,
                                       m.tasks[u].name, why));
    }
    for (const std::size_t g : regions[r])
      if (!route_to_region(w, trav, robot.start, m.regions[g]))
        throw InputError(fmt::format("regions[{}]", g),
                         fmt::format("region {} is unreachable for robot {} (radius {} m) from its "
                                     "start {}: no cell of the region is clear of the walls by its "
                                     "radius plus half a cell and connected to the start",
                                     m.regions[g].name, robot.name, robot.radius,
                                     point_text(robot.start)));
  }
}

}  // namespace swarmcheck::mission
