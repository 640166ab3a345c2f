#pragma once
// The world of a mission (issue 14): an occupancy grid of walls, robots of a radius, and the
// global path planner on the grid (A*). The mission file's optional "world":
//
//   "world": { "resolution_m": 0.5, "origin": [x, y],     lower-left corner of the grid
//              "rows": ["..........", "....##....", ...] }  '#' occupied, '.' free; the first
//                                                           row is the top (largest y)
//
// Cell (i, j) (row i from the top, column j) is the closed square [x0, x0 + res] x [y0, y0 + res]
// with x0 = origin x + j res and y0 = origin y + (rows - 1 - i) res. Outside the grid is wall.
//
// Overlap (the invariant checked every step): a robot of radius rho at p overlaps an obstacle
// when its disk leaves the grid's rectangle (p x - rho < origin x, ...), or some occupied cell's
// square is at distance < rho from p, or contains p in its interior.
//
// Planning: a cell is *traversable* for radius rho when it is free and every occupied cell and
// the grid's border are at distance >= rho + res / 2 from its square (the half cell is the margin
// that keeps a unicycle, which stops within its 5 cm tolerance of a waypoint and turns, clear of
// the walls). A* over cells, 8-connected (a diagonal move only when both cells beside it are
// traversable, so no corner is cut), steps of res and res * sqrt(2) summed in path order, the
// octile distance to the goal cells' bounding box as heuristic; the open cell of least f, ties by
// row-major index, is expanded next, so the path is deterministic. The start cell (where the
// robot is) need not be traversable; a goal cell must be, unless it is the start cell.
// A route follows the path's cells: its waypoints are the centres of the cells where the path
// turns, then the goal point (a task) or the last cell's centre (a region). Every segment lies in
// the union of the path's traversable squares (and the start cell's), so its clearance is at
// least rho + res / 2 there. Its length is the sum of distance() along from, waypoints... in order.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "spec/mission/mission.hpp"

namespace swarmcheck::mission {

struct Route {
  std::vector<Point> waypoints;  // non-empty; the last is the goal
  double length_m = 0.0;
};

// The cell containing p (row-major index), if p is in the grid (the top and right edges belong
// to the last row and column).
std::optional<std::size_t> cell_of(const GridWorld& w, const Point& p);
Point cell_centre(const GridWorld& w, std::size_t cell);

bool overlaps_obstacle(const GridWorld& w, const Point& p, double radius_m);
// The occupied cells the disk overlaps (the second part of overlaps_obstacle), bottom row first.
std::vector<std::size_t> overlapped_cells(const GridWorld& w, const Point& p, double radius_m);
// The disk leaves the grid's rectangle (the first part of overlaps_obstacle).
bool leaves_grid(const GridWorld& w, const Point& p, double radius_m);

// Per cell: traversable for radius_m (see above).
std::vector<char> traversable_cells(const GridWorld& w, double radius_m);

// The route from `from` to the point `to`, or to the nearest (by the A* path) traversable cell
// whose centre lies strictly inside `region`; nothing when there is none.
std::optional<Route> route_to_point(const GridWorld& w, const std::vector<char>& traversable,
                                    const Point& from, const Point& to);
std::optional<Route> route_to_region(const GridWorld& w, const std::vector<char>& traversable,
                                     const Point& from, const Region& region);

// The cost model's travel of robot r from `from` to `to`: distance(from, to) without a world
// (bit for bit today's), else route_to_point's length (+infinity when there is no route;
// check_mission rejects missions where a robot could need one).
double travel_cost(const Mission& m, std::size_t robot, const Point& from, const Point& to);

// Cells of a world at most (1 M: a 1 km square at 1 m), and neighbour checks traversable_cells
// may make for one robot (cells x (2 reach + 1)^2, reach = ceil((radius + res/2) / res) + 1):
// check_mission refuses a radius over the budget instead of computing for minutes.
inline constexpr std::size_t kMaxWorldCells = std::size_t{1} << 20;
inline constexpr double kMaxTraversableChecks = 268435456.0;  // 2^28
inline constexpr double kMaxScanSamples = 4194304.0;          // 2^22 samples a range scan
double traversable_checks(const GridWorld& w, double radius_m);

// The grid of the file (resolution, row lengths and characters checked; InputError at world.*);
// traversable is left empty (check_mission fills it per robot).
GridWorld build_world(const WorldDecl& d);

// check_mission's world checks (throws InputError at a JSON path): a start or task covered by an
// obstacle, a task (from the start and from each other task of the robot) or region of a robot's
// events unreachable from its start.
void check_world(const Mission& m);

}  // namespace swarmcheck::mission
