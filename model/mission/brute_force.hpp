#pragma once
// The oracle for small instances: every path of the FSM from q.from, as a walk over nodes
// (state, each robot's position) that never repeats a node, evaluated by the spec's cost model;
// the best (swarmcheck::mission::better), the first found on ties (events tried in name order).
// A walk that repeats a node is never better than the walk with the loop cut out (travel only
// grows), so the minimum over these walks is the minimum over all paths. Exponential: keep the
// FSM small. `max_walks` bounds the work; exceeding it throws std::length_error.
#include <cstddef>

#include "spec/mission/plan.hpp"

namespace swarmcheck::model::mission {

swarmcheck::mission::Plan brute_force_plan(const swarmcheck::mission::Mission& m,
                                     const swarmcheck::mission::PlanQuery& q,
                                     std::size_t max_walks = 2'000'000);

}  // namespace swarmcheck::model::mission
