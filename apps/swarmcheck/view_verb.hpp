#pragma once
#include <CLI/CLI.hpp>

namespace swarmcheck::cli {

// swarmcheck view FILE -o view.html [--max-records N] [--mission MISSION.json]
void add_view_verb(CLI::App& app, int& exit_code);

}  // namespace swarmcheck::cli
