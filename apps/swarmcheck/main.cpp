// swarmcheck: the command line. One file per verb; this file only wires them.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <string>
#include <vector>

#include "apps/swarmcheck/conform_verb.hpp"
#include "apps/swarmcheck/dse_verb.hpp"
#include "apps/swarmcheck/edit_verb.hpp"
#include "apps/swarmcheck/fmu_verb.hpp"
#include "apps/swarmcheck/fsm_verb.hpp"
#include "apps/swarmcheck/mission_verb.hpp"
#include "apps/swarmcheck/prove_verb.hpp"
#include "apps/swarmcheck/run_verb.hpp"
#include "apps/swarmcheck/serve_verb.hpp"
#include "apps/swarmcheck/view_verb.hpp"
#include "apps/swarmcheck/verb.hpp"
#include "impl/io/interrupt.hpp"

int main(int argc, char** argv) {
  swarmcheck::impl::io::install_interrupt_cleanup();   // Ctrl-C: temp files removed, exit 130
  CLI::App app{
      "swarmcheck: multi-robot exploration and FSM-supervised missions, simulated and checked"};
  app.require_subcommand(1);
  app.footer(
      "Exit status: 0 ok; 1 a negative verdict (a divergence, a blocking or uncontrollable "
      "supervisor, a run not completed or stalled, a refuted obligation); 2 bad input or a "
      "request refused (a budget, an output that is an input, a FIFO or device as output); 3 "
      "internal error (a bug: please report it); 130 / 143 / 129 interrupted by SIGINT / SIGTERM / "
      "SIGHUP (outputs left as they were; serve exits 0).");
  app.set_version_flag("--version", "swarmcheck 0.1.0");
  // Usage errors read like every other error: one line, the same prefix, and where help is.
  std::string path = "swarmcheck";   // the verbs named on the command line (below)
  app.failure_message([&path](const CLI::App*, const CLI::Error& e) {
    return std::string("swarmcheck: error: ") + e.what() + " (" + path + " --help shows the usage)\n";
  });
  int exit_code = 0;
  swarmcheck::cli::add_run_verb(app, exit_code);
  swarmcheck::cli::add_conform_verb(app, exit_code);
  swarmcheck::cli::add_replay_verb(app, exit_code);
  swarmcheck::cli::add_fsm_verb(app, exit_code);
  swarmcheck::cli::add_prove_verb(app, exit_code);
  swarmcheck::cli::add_mission_verb(app, exit_code);
  swarmcheck::cli::add_dse_verb(app, exit_code);
  swarmcheck::cli::add_view_verb(app, exit_code);
  swarmcheck::cli::add_edit_verb(app, exit_code);
  swarmcheck::cli::add_serve_verb(app, exit_code);
  swarmcheck::cli::add_fmu_verb(app, exit_code);
  swarmcheck::cli::add_cosim_verb(app, exit_code);
  // A verb that is not one (CLI11 would only say "A subcommand is required"): named, with the
  // verbs there are at that level.
  CLI::App* level = &app;
  for (int i = 1; i < argc && argv[i][0] != '-'; ++i) {
    const std::vector<CLI::App*> verbs = level->get_subcommands([](CLI::App*) { return true; });
    if (verbs.empty()) break;   // a verb's own arguments
    CLI::App* next = nullptr;
    std::string names;
    for (CLI::App* v : verbs) {
      if (v->check_name(argv[i])) next = v;
      names += (names.empty() ? "" : ", ") + v->get_name();
    }
    if (!next) {
      std::fprintf(stderr, "swarmcheck: error: unknown verb '%s' for %s (the verbs: %s)\n",
                   swarmcheck::cli::printable_message(argv[i]).c_str(), path.c_str(), names.c_str());
      return 2;
    }
    path += " " + next->get_name();
    level = next;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;  // usage errors are bad input: status 2
  }
  return exit_code;
}
