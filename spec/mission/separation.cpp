// Robots never overlap each other: the yield rule's test and the clearance of a set of poses.
#include "spec/mission/separation.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "spec/util/demand.hpp"
#include "spec/util/input_error.hpp"

namespace swarmcheck::mission {

double distance_to_segment(const Point& p, const Point& a, const Point& b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double len2 = dx * dx + dy * dy;
  if (len2 == 0.0) return distance(p, a);
  const double t = std::clamp(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2, 0.0, 1.0);
  return distance(p, {a[0] + t * dx, a[1] + t * dy});
}

std::optional<std::size_t> yields_to(const Mission& m, std::size_t i, const Point& from,
                                     const Point& p, std::span<const RobotWay> ways) {
  SWARM_DEMAND(ways.size() == m.robots.size());
  SWARM_DEMAND(i < ways.size());
  for (std::size_t j = 0; j < ways.size(); ++j) {
    if (j == i) continue;
    const double apart = m.robots[i].radius + m.robots[j].radius;
    if (distance(p, ways[j].at) < apart) return j;
    if (j > i || !ways[j].has_way || apart == 0.0) continue;  // points keep no distance
    if (ways[j].yielded_to == i) continue;  // j waits for i: i clears its way
    const double to = distance_to_segment(p, ways[j].at, ways[j].waypoint);
    if (to < apart + kWayMargin_m && to < distance_to_segment(from, ways[j].at, ways[j].waypoint))
      return j;
  }
  return std::nullopt;
}

double clearance_m(const Mission& m, std::span<const Point> positions) {
  SWARM_DEMAND(positions.size() == m.robots.size());
  double out = kNoClearance;
  for (std::size_t a = 0; a < positions.size(); ++a)
    for (std::size_t b = a + 1; b < positions.size(); ++b)
      out = std::min(out, distance(positions[a], positions[b]) -
                              (m.robots[a].radius + m.robots[b].radius));
  return out;
}

void check_robots_apart(const Mission& m) {
  for (std::size_t j = 0; j < m.robots.size(); ++j)
    for (std::size_t i = 0; i < j; ++i) {
      const Robot& a = m.robots[i];
      const Robot& b = m.robots[j];
      if (distance(a.start, b.start) < a.radius + b.radius)
        throw InputError(fmt::format("robots[{}].start", j),
                         fmt::format("robot {} (radius {} m) at [{}, {}] overlaps robot {} (radius "
                                     "{} m) at [{}, {}]: starts must be at least the sum of the "
                                     "radii apart",
                                     b.name, b.radius, b.start[0], b.start[1], a.name, a.radius,
                                     a.start[0], a.start[1]));
    }
}

}  // namespace swarmcheck::mission
