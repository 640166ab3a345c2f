#pragma once
// Robots never overlap each other (issue 14). Robot i is a disk of radius r_i (Robot::radius,
// 0 by default) centred on its position. Two robots i and j at p and q *overlap* when
//   distance(p, q) < r_i + r_j            (touching is allowed; point robots never overlap)
// The run rule (spec/mission/run.hpp, rule 3) keeps every pair apart at every step: robots move
// in index order (robots before i have moved already in this step), and robot i *yields* (keeps
// its whole state for the step) when its proposal p, from its position `from`, would
//  - overlap robot j's current position (any j != i): distance(p, at_j) < r_i + r_j; or
//  - (when r_i + r_j > 0) come closer to the *way* of a robot j < i that has a task, the segment from at_j to its
//    current waypoint, than r_i + r_j + kWayMargin_m, and closer than from is:
//    d(p) < r_i + r_j + kWayMargin_m and d(p) < d(from), d the distance to the segment.
// except when j yielded to i itself in this step (then i must clear j's way, not keep off it).
// The first j in index order decides. So the lower index has the right of way: a later robot
// stops short of an earlier robot's way instead of meeting it where the two ways cross (which
// would leave both waiting for ever), and it may always move away from that way. The margin
// covers the unicycle's small departures from the straight segment. Since the starts are apart
// (check_robots_apart) and a move is taken only when it overlaps nobody, no two robots overlap
// after any robot's move.
#include <cstddef>
#include <limits>
#include <optional>
#include <span>

#include "spec/mission/mission.hpp"

namespace swarmcheck::mission {

inline constexpr double kWayMargin_m = 0.25;

// What robot i's yield test sees of robot j: where it is, and its way when it has a task.
struct RobotWay {
  Point at{};
  bool has_way = false;  // it has a queued task (and so a waypoint)
  Point waypoint{};
  std::optional<std::size_t> yielded_to;  // the robot it yielded to in this step, if it did
  bool stuck = false;  // ... and it was in a standoff with no way aside (spec/mission/steering.hpp)
};

// The distance from p to the segment [a, b] (to a when a == b): the point a + t (b - a),
// t = clamp(((p - a) . (b - a)) / |b - a|^2, 0, 1), then distance().
double distance_to_segment(const Point& p, const Point& a, const Point& b);

// The first robot j != i (index order) robot i yields to by the rule above, moving from `from`
// to p, the others as `ways` (ways[i] is ignored); nothing when it yields to no one.
std::optional<std::size_t> yields_to(const Mission& m, std::size_t i, const Point& from,
                                     const Point& p, std::span<const RobotWay> ways);

// The least gap distance(p_a, p_b) - (r_a + r_b) over the pairs a < b (a outer, b inner, the
// minimum taken in that order); +infinity with fewer than two robots. >= 0 iff no two overlap.
double clearance_m(const Mission& m, std::span<const Point> positions);
inline constexpr double kNoClearance = std::numeric_limits<double>::infinity();

// check_mission's check that the starts are apart: robots[j].start (j > i, the first such pair in
// that order) overlapping robot i's start is an InputError.
void check_robots_apart(const Mission& m);

}  // namespace swarmcheck::mission
