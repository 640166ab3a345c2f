#include "conformance/exploration/transition.hpp"

#include <cstdlib>

#include "spec/exploration/handshake.hpp"
#include "spec/exploration/invariants.hpp"
#include "spec/exploration/neighbourhood.hpp"

namespace swarmcheck::conformance::exploration {

using namespace swarmcheck::exploration;

namespace {

std::string check_robots(const Scenario& s, const StepRecord& before, const StepRecord& after, bool planned) {
  for (std::size_t k = 0; k < after.robots.size(); ++k) {
    const CellIndex a = before.robots[k].cell, b = after.robots[k].cell;
    const std::string who = "robots[" + std::to_string(k) + "]";
    const bool moved = a != b;
    if (moved && !planned) return who + " changed cell on a step without planning";
    if (moved && std::max(std::abs(a[0] - b[0]), std::abs(a[1] - b[1])) > s.params.s_range)
      return who + " moved further than s_range";
    if (moved && after.robots[k].waypoint != centre_of(b, s.cell_size))
      return who + "'s waypoint is not the centre of its new cell";
    if (!moved && after.robots[k].waypoint != before.robots[k].waypoint)
      return who + "'s waypoint changed although it stayed";
  }
  return {};
}

}  // namespace

std::string check_transition(const Scenario& s, const StepRecord& before, const StepRecord& after) {
  if (after.step != before.step + 1) return "the step counter did not advance by one";
  const int64_t planned_count = after.planning_steps - before.planning_steps;
  if (planned_count != 0 && planned_count != 1) return "planning_steps advanced by more than one";
  const bool planned = planned_count == 1;
  if (s.mode == Mode::cosim) {
    bool all_arrived = true;
    for (const auto& r : before.robots) all_arrived = all_arrived && r.controller.on_destination_output == 1;
    const HandshakeStep hs = environment_handshake(before.handshake, all_arrived);
    if (hs.plan != planned) return "planned against the handshake table";
    if (hs.next.flag != after.handshake.flag || hs.next.on_destination_output != after.handshake.on_destination_output)
      return "the handshake state does not follow the table";
  } else if (!planned) {
    return "an abstract step did not plan";
  }
  if (std::string e = check_robots(s, before, after, planned); !e.empty()) return e;
  if (after.visited < before.visited) return "visited decreased";
  if (rules_of(s.rule).keeps_occupancy_invariants)
    if (std::string e = check_occupancy(s, after.robots); !e.empty()) return e;
  if (std::string e = check_progress(s, after); !e.empty()) return e;
  if (std::string e = check_servos(after.robots); !e.empty()) return e;
  return {};
}

}  // namespace swarmcheck::conformance::exploration
