#pragma once
// The differential runner: the reference model and the optimised library side by side, the
// whole observable state compared after every step (doubles by bits): the step record, and on
// planning steps (and the last) every cell of the grid. Each model step is also checked against
// the spec's transition rules.
#include <cstdint>
#include <optional>
#include <string>

#include "spec/exploration/types.hpp"
#include "swarmcheck/exploration.hpp"

namespace swarmcheck::conformance {

struct Divergence {
  int64_t step;         // the first step (after step 0, the initial state) that differs
  std::string path;     // e.g. "robots[2].cell" or "cells[3][4].pheromone"
  std::string model;    // the model's value as text
  std::string impl;     // the impl's value (or, for a spec violation, the broken rule)
  bool spec_violation;  // the model broke a transition rule (impl not compared)
  std::string describe() const;   // "step 17: robots[2].cell model=(3,4) impl=(4,4)"
};

// Runs both for at most s.max_steps steps (or until both are done).
std::optional<Divergence> run_lockstep(const exploration::Scenario& s, const ExplorationOptions& options);

}  // namespace swarmcheck::conformance
