#pragma once
// `swarmcheck conform --fmu`: anyone's Environment, Controller and Body FMUs against the model
// (conformance/fmu/fmu_conform.hpp), on the command line.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "apps/swarmcheck/robot_options.hpp"

namespace swarmcheck::cli {

struct ConformFmuArgs {
  std::vector<std::string> fmus;
  std::string interface = "swarmcheck";
  std::string rule;                 // empty: every rule set drawn
  RobotChoiceOptions robots;        // what the model runs
  double tolerance = 0.0, relative_tolerance = 0.0;
};

void add_conform_fmu_options(CLI::App* cmd, ConformFmuArgs& a);

// The campaign; status 0 (agree), 1 (a counterexample) or an InputError.
int conform_fmu(const ConformFmuArgs& a, int cases, bool cases_given, uint64_t seed, int64_t max_steps,
                const std::string& out_dir, double case_time_limit_s, bool json);

}  // namespace swarmcheck::cli
