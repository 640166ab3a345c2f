#pragma once
// Differential runners for missions: the library against the model on the same input, with the
// first difference described (nothing when they agree).
//
// diff_run: the library's run_mission against model/mission/run_model (which follows the
//   library's exact planner, see run_model.hpp), comparing the whole RunResult and every event
//   and step record the observer saw, doubles by their bits: "steps[12].positions[0]: impl
//   (1,2) model (1,3)". `model_plan`, when given, replaces the model's planner (the canary's way
//   of planting a wrong choice).
// `progress` (in a child process) is told which side runs and, in a run, the step it is at.
// diff_plan: the library's exact planner against the model's brute force on one query: both
//   find a plan or neither, with the same objective (makespan, total) bit for bit, and the exact
//   plan is an FSM path to a marked state with the cost (per-robot travel included) it states.
#include <functional>
#include <optional>
#include <string>

#include "conformance/common/child_process.hpp"
#include "spec/mission/plan.hpp"
#include "spec/mission/run.hpp"

namespace swarmcheck::conformance::mission {

using PlanFunction =
    std::function<swarmcheck::mission::Plan(const swarmcheck::mission::PlanQuery&)>;

std::optional<std::string> diff_run(const swarmcheck::mission::Mission& m,
                                    const swarmcheck::mission::RunOptions& o,
                                    const PlanFunction& model_plan = {}, CaseProgress* progress = nullptr);

std::optional<std::string> diff_plan(const swarmcheck::mission::Mission& m,
                                     const swarmcheck::mission::PlanQuery& q, CaseProgress* progress = nullptr);

}  // namespace swarmcheck::conformance::mission
