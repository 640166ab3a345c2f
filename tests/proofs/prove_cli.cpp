// A private command line with only the prove verb, wired exactly as apps/swarmcheck/main.cpp
// wires its verbs, so the verb's tests run before main.cpp registers it.
#include <CLI/CLI.hpp>

#include "apps/swarmcheck/prove_verb.hpp"

int main(int argc, char** argv) {
  CLI::App app{"swarmcheck (prove only, for tests)"};
  app.require_subcommand(1);
  int exit_code = 0;
  swarmcheck::cli::add_prove_verb(app, exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  return exit_code;
}
