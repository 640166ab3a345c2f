#pragma once
// Unknown obstacles and the range sensor (issue 14). A world may declare
//   "unknown_obstacles": [{"polygon": [[x, y], ...]}, ...]   rasterised like "obstacles"
//   "sensor": {"beams": N, "range_m": R, "noise_m": sigma}   default 64 beams, 3 m, no noise
// Unknown obstacles are in the world (a robot's disk must never overlap them) but not on the
// map the robots start with: GridWorld::occupied is the map, GridWorld::hidden the cells only
// the world has. Planning (costs, routes, the world's checks) uses the map.
//
// Scan (every motion step, per robot with a queued task, before its proposal): beam k of N
// points at angle 2 pi k / N (world frame). Its true range is the first t = n res / 8
// (n = 1, 2, ...; t <= R) at which p + t (cos, sin) lies outside the grid or in a cell occupied
// in the world (map or hidden), else R with no return (the reading is R, exactly: no noise).
// A return's reading is clamp(t + sigma g, 0, R), g a standard
// normal drawn from (seed, step, robot, beam): u = splitmix64 chain, two uniforms in (0, 1],
// Box-Muller's sqrt(-2 ln u1) cos(2 pi u2). A reading below R puts the cell of
// p + reading (cos, sin) (when in the grid) on the robot's own map.
// When a scan adds a cell to a robot's map, the robot's traversable cells are recomputed on its
// map and its leg restarts from where it is (rule 3's leg start, routes on its own map):
// replans_sensed counts these. A proposal overlapping the world (map or hidden) is a bump: the
// robot keeps its state for the step, the cells its disk would overlap go on its map (the same
// re-routing when one is new), and bumps counts it.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "spec/mission/mission.hpp"

namespace swarmcheck::mission {

// The world as it is: map and hidden cells together (the map alone when nothing is hidden).
GridWorld true_world(const GridWorld& w);

// A standard normal from the key (seed, step, robot, beam), as described above.
double sensor_normal(std::uint64_t seed, std::uint64_t step, std::uint64_t robot, std::uint64_t beam);

// The cells a scan from p puts on a map (in beam order, possibly repeated), `truth` the world.
std::vector<std::size_t> scan_cells(const GridWorld& truth, const Point& p, std::uint64_t seed,
                                    std::uint64_t step, std::uint64_t robot);

// Adds `cells` to `map`; true when one of them was not on it.
bool add_to_map(std::vector<char>& map, const std::vector<std::size_t>& cells);

// The map's traversable cells for radius_m (traversable_cells on w with `map` as occupancy).
std::vector<char> traversable_on(const GridWorld& w, const std::vector<char>& map, double radius_m);

}  // namespace swarmcheck::mission
