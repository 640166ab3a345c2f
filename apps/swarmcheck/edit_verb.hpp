#pragma once
#include <CLI/CLI.hpp>

namespace swarmcheck::cli {

// swarmcheck edit [SCENARIO.json | MISSION.json] -o editor.html
void add_edit_verb(CLI::App& app, int& exit_code);

}  // namespace swarmcheck::cli
