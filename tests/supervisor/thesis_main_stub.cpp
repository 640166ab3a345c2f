// A private `swarmcheck` with only the fsm verb, for the thesis tests and manual runs until
// main.cpp wires add_fsm_verb (the lead's file). Same exit statuses as main.cpp.
#include <CLI/CLI.hpp>

#include "apps/swarmcheck/fsm_verb.hpp"

int main(int argc, char** argv) {
  CLI::App app{"swarmcheck (fsm verb only)"};
  app.require_subcommand(1);
  int exit_code = 0;
  swarmcheck::cli::add_fsm_verb(app, exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;
  }
  return exit_code;
}
