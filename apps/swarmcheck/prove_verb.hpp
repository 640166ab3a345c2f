#pragma once
// `swarmcheck prove [--only NAME] [--smt2 DIR] [--trace-dir DIR] [--json]`: checks the Z3 proof
// obligations of proofs/ and prints obligation, expected, result and seconds. Exit status 0
// when every result is the expected verdict, 1 otherwise, 2 on bad input.
#include <CLI/CLI.hpp>

namespace swarmcheck::cli {

void add_prove_verb(CLI::App& app, int& exit_code);

}  // namespace swarmcheck::cli
