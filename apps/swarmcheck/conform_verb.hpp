#pragma once
#include <CLI/CLI.hpp>

namespace swarmcheck::cli {

// swarmcheck conform [--cases N] [--seed S] [--max-steps K] [--out DIR] [--json]
void add_conform_verb(CLI::App& app, int& exit_code);
// swarmcheck replay TRACE [--against model|impl]
void add_replay_verb(CLI::App& app, int& exit_code);

}  // namespace swarmcheck::cli
