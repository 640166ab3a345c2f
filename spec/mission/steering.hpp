#pragma once
// Local steering around robots, VFH-style (issue 14; the thesis's GoGoal drove with a Vector
// Field Histogram). Rule 3 (spec/mission/run.hpp) makes a robot *yield* when its move would
// overlap another robot or cut an earlier robot's way. Waiting is right while the other robot
// moves on; it is a *standoff* (`standoff`) when the other robot j waits for i: j yielded at
// its last turn to move to i (two robots head-on), or to a robot that waits for i in turn (the
// chain of yields, followed at most once round the robots, reaches i). Where a robot k of the
// chain comes after i in index order its yield was in the step before, and counts only when k was
// *stuck* then (it yielded in a standoff of its own, finding no way aside). So head-on, the later
// robot steers first, and the earlier one only when the later finds no way aside; an earlier
// robot never steers because a later one merely waited for it. In a standoff robot i steers
// instead of waiting. A robot parked in the way (no queued task) is no standoff: the robot waits
// for it, and a run where nothing else moves ends in the deadlock that names it (steering round
// it and re-planning straight through it again would go back and forth until the time limit).
//
// Binary polar histogram. Around the robot (at p, radius r) sector k of kSteerSectors points at
// a_k = 2 pi k / kSteerSectors (world frame). Sector k is *free* when the robot's disk swept
// along the segment s_k from p to e_k = p + kSteerLookahead_m (cos a_k, sin a_k) meets nothing
// the robot knows of:
//  - every other robot j at q_j: distance_to_segment(q_j, p, e_k) >= r + r_j (the two disks
//    never overlap along s_k; rule 3 still checks the move itself every step);
//  - in a world, on the robot's map (the world's map, or its own with unknown obstacles): e_k's
//    disk stays in the grid's rectangle with kSteerPad_m to spare, every occupied square is at
//    distance >= r + kSteerPad_m from s_k (segment-to-square distance, exact), and e_k lies in a
//    cell traversable for the robot (so the route it plans from there is as safe as any other).
// Candidates: the free sectors within 100 degrees of the bearing from p to the robot's waypoint
// (in sectors, b = atan2(dy, dx) S / (2 pi), S = kSteerSectors; the angular distance
// d_k = |remainder(k - b, S)| <= S 100 / 360), by d_k, then by k. (A little more than sideways:
// two robots that stopped touching, nearly in line, find both sideways sectors just blocked. Not
// further back: a robot never retreats along its way, so a corridor too narrow to pass stays a
// reported deadlock instead of a back-and-forth until the time limit.)
// Rule 3 tries them in that order: the candidate's detour point e_k becomes the robot's leg (a
// fresh leg: no route, the controller takes e_k as a new waypoint), and the first whose proposal
// passes the checks of rule 3 (no overlap with the world, no yield) is the robot's move; `steers`
// counts it. Arrived at e_k, the robot starts its next leg from there (A* again). No candidate
// passes: the robot yields, as before.
#include <cstddef>
#include <span>
#include <vector>

#include "spec/mission/mission.hpp"
#include "spec/mission/separation.hpp"

namespace swarmcheck::mission {

inline constexpr std::size_t kSteerSectors = 72;   // 5 degrees each
inline constexpr double kSteerLookahead_m = 0.5;   // the length of a detour
inline constexpr double kSteerPad_m = 0.05;        // the unicycle's departures from the segment

// The distance from the segment [a, b] to the closed axis-aligned square [lo, hi] (0 when they
// meet: Liang-Barsky clipping; otherwise the least of the endpoints' distances to the square and
// the corners' distances to the segment).
double segment_square_distance(const Point& a, const Point& b, const Point& lo, const Point& hi);

// What robot i's histogram sees: the positions of all robots (its own ignored), and in a world
// its map and traversable cells (null without a world).
struct SteerView {
  std::span<const Point> positions;
  const std::vector<char>* map = nullptr;
  const std::vector<char>* traversable = nullptr;
};

// Robot i, yielding to robot j, is in a standoff (see above).
bool standoff(std::size_t i, std::size_t j, std::span<const RobotWay> ways);

// Robot i's detour points e_k at `at`, heading for `waypoint`, in the order rule 3 tries them.
std::vector<Point> steer_candidates(const Mission& m, std::size_t i, const Point& at,
                                    const Point& waypoint, const SteerView& view);

}  // namespace swarmcheck::mission
