#pragma once
// The two mission planners behind one interface: the library's exact planner and the thesis's
// modified Dijkstra (the baseline, kept in the model with its bugs). The command line's
// `mission plan --planner exact|thesis` chooses here, so that only the harness reaches model/.
#include <string>

#include "swarmcheck/mission.hpp"

namespace swarmcheck::conformance::mission {

enum class PlannerKind { exact, thesis };

// "exact" or "thesis"; anything else is an InputError.
PlannerKind planner_named(const std::string& name);

swarmcheck::mission::Plan plan(const swarmcheck::mission::Mission& m,
                               const swarmcheck::mission::PlanQuery& q, PlannerKind kind);

}  // namespace swarmcheck::conformance::mission
