#pragma once
#include <CLI/CLI.hpp>

namespace swarmcheck::cli {

// swarmcheck run [SCENARIO.json] [--mode M] [--rule R] [--seed N] [--steps N] [--trace FILE]
//                [--trace-every K] [--json]
void add_run_verb(CLI::App& app, int& exit_code);

}  // namespace swarmcheck::cli
