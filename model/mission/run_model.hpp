#pragma once
// The reference model of a mission run: the rules of spec/mission/run.hpp as the obvious
// fixed-step loop over plain values (no caching, no incremental state), the oracle the library's
// runner is compared against (conformance/mission/differential).
//
// The planner is a parameter. The spec asks for exact plans, and among plans of equal cost the
// planner's own order decides which one a run follows; a model with another planner would follow
// other (equally good) plans. The harness passes the library's exact planner here, whose plans
// are checked separately against brute force (model/mission/brute_force), so that this loop is
// judged on everything else: choice, legs and detours, motion, region entries, blocking,
// deadlock, the records and the counters.
#include <functional>

#include "spec/mission/plan.hpp"
#include "spec/mission/run.hpp"

namespace swarmcheck::model::mission {

using PlanFunction =
    std::function<swarmcheck::mission::Plan(const swarmcheck::mission::PlanQuery&)>;

swarmcheck::mission::RunResult run_model(const swarmcheck::mission::Mission& m,
                                         const swarmcheck::mission::RunOptions& o,
                                         const PlanFunction& plan,
                                         swarmcheck::mission::RunObserver* observer = nullptr);

}  // namespace swarmcheck::model::mission
