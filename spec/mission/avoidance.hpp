#pragma once
// The region-entry rule of execution (DESIGN.md B5). Robots move in continuous space; robot r
// *enters* region g on a step when its position goes from outside g to strictly inside it. If
// the mission gives that entry a meaning (an uncontrollable event e of the FSM), e fires; and
// the avoidance rule says: a robot never enters a region whose entry event the supervisor does
// not allow in the current state. The executor obeys it by keeping a robot where it is for a
// step whose entries are not all enabled, in turn, from the current state; it resumes when they
// are. Entering a region that has no event for the robot is always free.
#include <optional>
#include <string>
#include <vector>

#include "spec/mission/mission.hpp"

namespace swarmcheck::mission {

// The entry events robot r fires moving from `from` to `to`, regions in file order.
std::vector<std::string> entry_events(const Mission& m, std::size_t robot, const Point& from,
                                      const Point& to);

// The state after firing `events` in turn from q, or nothing when one of them is not enabled.
std::optional<std::string> fire_all(const Mission& m, const std::string& q,
                                    const std::vector<std::string>& events);

}  // namespace swarmcheck::mission
