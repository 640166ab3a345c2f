#pragma once
// RapidCheck generators of exploration cases for the differential harness (type-directed, so
// nearly every case is a valid scenario that reaches deep code): maps 1..64, robots from one to
// a good share of the free cells, obstacles, every rule set and mode, parameters including their
// edge values (phi <= 0, ertu * step_size >= 1, s_range beyond the map, epsilon 0, tiny and huge
// a1 / a2), seeds; and whether the impl plans by parallel groups even for few robots.
#include <rapidcheck.h>

#include "spec/exploration/types.hpp"
#include "swarmcheck/exploration.hpp"

namespace swarmcheck::conformance {

struct ExplorationCase {
  exploration::Scenario scenario;
  bool grouped = false;   // impl option: plan by independent groups (parallel path) always
};

// max_steps: the steps each case runs at most (the scenario's max_steps is set to it).
rc::Gen<ExplorationCase> gen_exploration_case(int64_t max_steps);

ExplorationOptions impl_options(const ExplorationCase& c);

}  // namespace swarmcheck::conformance
