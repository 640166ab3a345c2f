#pragma once
// The conformance campaign: generated cases, each run in lock-step on the model and the impl;
// on the first divergence RapidCheck shrinks the case to a minimal one, whose trace is written.
// One seed drives everything: the same options give the same cases and the same counterexample.
// Each case runs in a child process (conformance/common/child_process.hpp): an impl that crashes
// or hangs on a case diverges there ("step 12: impl crashed with SIGSEGV at step 12"), and that
// case shrinks like any other.
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>

#include "conformance/exploration/generators.hpp"
#include "conformance/exploration/lockstep.hpp"

namespace swarmcheck::conformance::exploration {

struct ConformOptions {
  int cases = 200;             // generated cases (RapidCheck's max_success)
  uint64_t seed = 1;
  int64_t max_steps = 120;     // steps per abstract case (cosim cases run 3x as many)
  std::string out_dir = "conform-out";
  // A case whose run reaches no new step for this long is stopped: the impl (or the model) hung.
  std::chrono::milliseconds quiet_limit{std::chrono::seconds(60)};
  // Called after each case with (cases done, cases asked); may print progress.
  std::function<void(int, int)> on_case;
};

struct Counterexample {
  ExplorationCase minimal;     // after shrinking
  Divergence divergence;
  std::string trace_path;
  int shrinks = 0;             // accepted shrink steps
  Family caught_by = Family::standard;   // the family of the case that first failed (before shrinking)
};

// What the campaign reached, by the classes of state a fault may hide in (conform --stats,
// docs/harness.md): the cases of each family and what they got to.
struct Coverage {
  std::map<std::string, int> cases_by_family;      // standard, long_horizon, edge_poses
  std::map<std::string, int> cases_by_rule_mode;   // "thesis/abstract", ...
  int grouped_cases = 0;            // the impl planned and deposited in parallel
  int64_t longest_run_steps = 0;
  int64_t max_cell_age = 0;         // ticks between a nonzero cell's write and its evaluation
  int cases_age_past_2_12 = 0;      // past the lazy grid's decay table (4096)
  int cases_steps_past_2_15 = 0;    // ticks past 32768
  int negative_zero_starts = 0;     // cases with a robot starting at -0.0
  int off_centre_starts = 0;        // cases with a robot starting off its cell's centre
  int heading_near_pi_cases = 0;    // cases where a heading came within 0.05 rad of +-pi
  int completed_cases = 0;          // completion step, eP freeze and summary compared
  // Planning steps of grouped cases by how the robots' rows changed (LockstepReach): the strip
  // schedule's reuse of its lists, and the steps that must build them again.
  int64_t grouped_steps_rows_kept = 0, grouped_steps_one_row_changed = 0, grouped_steps_rows_exchanged = 0;
};

struct ConformReport {
  int cases_run = 0;
  Coverage coverage;                // of the cases before the first divergence
  std::optional<Counterexample> counterexample;
};

ConformReport run_conform(const ConformOptions& o);

// One case's lock-step run in a child process: its divergence (a crash or a hang included), or
// nothing. `reach` gets what the run reached when it ended normally.
std::optional<Divergence> run_case_isolated(const ExplorationCase& c, std::chrono::milliseconds quiet_limit,
                                            LockstepReach* reach = nullptr, bool* hung = nullptr);

}  // namespace swarmcheck::conformance::exploration
