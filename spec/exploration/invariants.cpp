#include "spec/exploration/invariants.hpp"

#include <set>

#include "spec/exploration/neighbourhood.hpp"

namespace swarmcheck::exploration {

std::string check_occupancy(const Scenario& s, std::span<const RobotRecord> robots) {
  std::set<CellIndex> obstacles(s.obstacles.begin(), s.obstacles.end());
  std::set<CellIndex> seen;
  for (std::size_t k = 0; k < robots.size(); ++k) {
    const CellIndex c = robots[k].cell;
    const std::string who = "robots[" + std::to_string(k) + "]";
    if (!in_map(c, s.map_size)) return who + " is outside the map";
    if (obstacles.count(c)) return who + " stands on an obstacle";
    if (!seen.insert(c).second) return who + " shares its cell with another robot";
  }
  return {};
}

std::string check_progress(const Scenario& s, const StepRecord& r) {
  if (r.visited < 0) return "visited is negative";
  if (rules_of(s.rule).keeps_occupancy_invariants && r.visited > r.free_cells)
    return "visited exceeds the free cells (a cell was counted twice)";
  if (!(r.eP >= 0)) return "eP is negative or NaN";
  if (rules_of(s.rule).keeps_occupancy_invariants && r.eP > 100.0) return "eP exceeds 100";
  if (!(r.sTime >= 0)) return "sTime is negative or NaN";
  return {};
}

std::string check_servos(std::span<const RobotRecord> robots) {
  for (std::size_t k = 0; k < robots.size(); ++k) {
    const auto& c = robots[k].controller;
    if (!(c.servo_left >= -1 && c.servo_left <= 1 && c.servo_right >= -1 && c.servo_right <= 1))
      return "robots[" + std::to_string(k) + "] has a servo command outside [-1, 1]";
  }
  return {};
}

}  // namespace swarmcheck::exploration
