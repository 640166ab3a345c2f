#pragma once
// `swarmcheck mission plan|run`: plan a supervised multi-robot mission, or run it in simulation.
#include <CLI/CLI.hpp>

namespace swarmcheck::cli {

void add_mission_verb(CLI::App& app, int& exit_code);

}  // namespace swarmcheck::cli
