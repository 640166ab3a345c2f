#pragma once
#include <CLI/CLI.hpp>

namespace swarmcheck::cli {

// swarmcheck serve [--port P] [--bind 127.0.0.1]
void add_serve_verb(CLI::App& app, int& exit_code);

}  // namespace swarmcheck::cli
