#pragma once
// The differential runner: the reference model and the optimised library side by side, the
// whole observable state compared after every step (doubles by bits): the step record, done()
// and the completion step, on planning steps (and the last) every cell of the grid, and at the
// end the summary object the command line prints. Each model step is also checked against the
// spec's transition rules.
#include <cstdint>
#include <optional>
#include <string>

#include "conformance/common/child_process.hpp"
#include "spec/exploration/types.hpp"
#include "swarmcheck/exploration.hpp"

namespace swarmcheck::conformance::exploration {

struct Divergence {
  int64_t step;         // the first step (after step 0, the initial state) that differs
  std::string path;     // e.g. "robots[2].cell" or "cells[3][4].pheromone"
  std::string model;    // the model's value as text
  std::string impl;     // the impl's value (or, for a spec violation, the broken rule)
  bool spec_violation;  // the model broke a transition rule (impl not compared)
  // Not empty when the run ended abnormally in its child process (conformance/common/
  // child_process.hpp): "impl crashed with SIGSEGV at step 17"; path, model and impl are empty.
  std::string abnormal_end = {};
  // "step 17: robots[2].cell model=(3,4) impl=(4,4)", or the abnormal end.
  std::string describe() const;
};

// What one lock-step run reached (the harness's coverage figures, conform --stats).
struct LockstepReach {
  int64_t steps = 0;               // master steps run
  int64_t max_cell_age = 0;        // the largest age (ticks since written) of a nonzero cell evaluated
  int64_t planning_steps = 0;
  bool completed = false;
  bool heading_near_pi = false;    // some body heading came within 0.05 rad of +-pi
  bool negative_zero_start = false, off_centre_start = false;
  // Planning steps by how the robots' rows changed: the strip schedule keeps its robot lists
  // from one build to the next while every robot stays on its row (impl/exploration/
  // strip_schedule.hpp), so the steps that matter are those where none, exactly one, or only
  // robots exchanging rows (the same rows, as a multiset) moved off their rows.
  int64_t steps_rows_kept = 0, steps_one_row_changed = 0, steps_rows_exchanged = 0;
};

// Runs both for at most s.max_steps steps (or until both are done). `progress` (in a child
// process) is told each step and which engine is computing it.
std::optional<Divergence> run_lockstep(const swarmcheck::exploration::Scenario& s, const ExplorationOptions& options,
                                       LockstepReach* reach = nullptr, CaseProgress* progress = nullptr);

}  // namespace swarmcheck::conformance::exploration
