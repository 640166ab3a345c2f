#pragma once
// The differential runner: the reference model and the optimised library side by side, the
// whole observable state compared after every step (doubles by bits): the step record, done()
// and the completion step, on planning steps (and the last) every cell of the grid, and at the
// end the summary object the command line prints. Each model step is also checked against the
// spec's transition rules.
#include <cstdint>
#include <optional>
#include <string>

#include "spec/exploration/types.hpp"
#include "swarmcheck/exploration.hpp"

namespace swarmcheck::conformance::exploration {

struct Divergence {
  int64_t step;         // the first step (after step 0, the initial state) that differs
  std::string path;     // e.g. "robots[2].cell" or "cells[3][4].pheromone"
  std::string model;    // the model's value as text
  std::string impl;     // the impl's value (or, for a spec violation, the broken rule)
  bool spec_violation;  // the model broke a transition rule (impl not compared)
  std::string describe() const;   // "step 17: robots[2].cell model=(3,4) impl=(4,4)"
};

// What one lock-step run reached (the harness's coverage figures, conform --stats).
struct LockstepReach {
  int64_t steps = 0;               // master steps run
  int64_t max_cell_age = 0;        // the largest age (ticks since written) of a nonzero cell evaluated
  int64_t planning_steps = 0;
  bool completed = false;
  bool heading_near_pi = false;    // some body heading came within 0.05 rad of +-pi
  bool negative_zero_start = false, off_centre_start = false;
};

// Runs both for at most s.max_steps steps (or until both are done).
std::optional<Divergence> run_lockstep(const swarmcheck::exploration::Scenario& s, const ExplorationOptions& options,
                                       LockstepReach* reach = nullptr);

}  // namespace swarmcheck::conformance::exploration
