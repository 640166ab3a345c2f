#pragma once
// Generated missions (already consistent; built as values, not read from files).
//
// random_small_mission: 1..3 robots, 1..3 tasks, 2 regions, an FSM of 2..6 states whose edges
//   carry random task starts (controllable, "r<r>t<t>") and region entries (uncontrollable,
//   "r<r>g<g>") to random targets, 1..2 marked states. Small enough for brute force.
// allocation_mission(robots, tasks, seed): the task-allocation supervisor: a state records each
//   task as free, in progress by one robot, or done; "r<r>s<t>" (controllable) starts a free task
//   on an idle robot, "r<r>f<t>" (uncontrollable, entry into the 2 m square around the task) ends
//   it; marked: all done. Task points and starts uniform in [-20, 20]^2 from `seed`.
#include <cstdint>
#include <rapidcheck.h>

#include "spec/mission/mission.hpp"

namespace swarmcheck::conformance::mission {

rc::Gen<spec::mission::Mission> random_small_mission();

spec::mission::Mission allocation_mission(std::size_t robots, std::size_t tasks,
                                          std::uint64_t seed);

}  // namespace swarmcheck::conformance::mission
