#pragma once
// The conformance campaign: generated cases, each run in lock-step on the model and the impl;
// on the first divergence RapidCheck shrinks the case to a minimal one, whose trace is written.
// One seed drives everything: the same options give the same cases and the same counterexample.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "conformance/exploration/generators.hpp"
#include "conformance/exploration/lockstep.hpp"

namespace swarmcheck::conformance {

struct ConformOptions {
  int cases = 200;             // generated cases (RapidCheck's max_success)
  uint64_t seed = 1;
  int64_t max_steps = 120;     // steps per abstract case (cosim cases run 3x as many)
  std::string out_dir = "conform-out";
  // Called after each case with (cases done, cases asked); may print progress.
  std::function<void(int, int)> on_case;
};

struct Counterexample {
  ExplorationCase minimal;     // after shrinking
  Divergence divergence;
  std::string trace_path;
  int shrinks = 0;             // accepted shrink steps
};

struct ConformReport {
  int cases_run = 0;
  std::optional<Counterexample> counterexample;
};

ConformReport run_conform(const ConformOptions& o);

}  // namespace swarmcheck::conformance
