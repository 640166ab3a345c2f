#pragma once
// `swarmcheck fsm check|product|synth|export|compare` (and controllable|observable|project,
// fsm_control_verb.hpp): discrete-event automata in UMDES .fsm files
// (DESIGN.md B1-B2; docs/supervisor.md has an example of each).
#include <CLI/CLI.hpp>

namespace swarmcheck::cli {

void add_fsm_verb(CLI::App& app, int& exit_code);

}  // namespace swarmcheck::cli
