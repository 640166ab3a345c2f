#pragma once
#include <CLI/CLI.hpp>

namespace swarmcheck::cli {

// swarmcheck fmu export environment|controller|body [--robots N] [--scenario S.json] -o X.fmu
// swarmcheck fmu export --intocps DIR [--robots N] [--scenario S.json] [--handshake flag|epoch]
void add_fmu_verb(CLI::App& app, int& exit_code);

// swarmcheck cosim MULTIMODEL.json [--config COE.json] [--algorithm jacobi|gauss-seidel]
//                  [-o outputs.csv] [--json]
void add_cosim_verb(CLI::App& app, int& exit_code);

}  // namespace swarmcheck::cli
