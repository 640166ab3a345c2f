#pragma once
// `swarmcheck fsm controllable|project|observable`: a given supervisor's checks and partial
// observation (spec/supervisor/control.hpp, observation.hpp), added under `fsm`.
#include <CLI/CLI.hpp>

namespace swarmcheck::cli {

void add_fsm_control_subcommands(CLI::App* fsm, int& exit_code);

}  // namespace swarmcheck::cli
