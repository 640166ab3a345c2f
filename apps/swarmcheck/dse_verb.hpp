#pragma once
#include <CLI/CLI.hpp>

namespace swarmcheck::cli {

// swarmcheck dse CONFIG.dse.json [--scenario BASE.json] [-o DIR] [--threads N] [--json]
// (also under mpirun: rank 0 writes, the other ranks run design points)
void add_dse_verb(CLI::App& app, int& exit_code);

}  // namespace swarmcheck::cli
