// swarmcheck serve: the live page and the editor over HTTP on loopback (views/server.hpp has the
// routes and the limits). Runs until Ctrl-C (SIGINT) or SIGTERM.
#include "apps/swarmcheck/serve_verb.hpp"

#include <fmt/core.h>

#include "apps/swarmcheck/verb.hpp"
#include "views/server.hpp"

namespace swarmcheck::cli {

void add_serve_verb(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<views::ServeOptions>();
  CLI::App* cmd = app.add_subcommand("serve", "Serve the live view and the editor (loopback by default)");
  cmd->add_option("--port", o->port, "TCP port (0: any free port, printed)")->capture_default_str();
  cmd->add_option("--bind", o->bind, "Address to listen on (127.0.0.1: this machine only)")
      ->capture_default_str()
      ->check(CLI::Validator([](const std::string& t) { return t.empty() ? std::string("expected an address such as 127.0.0.1, got nothing") : std::string(); }, "ADDRESS"));
  cmd->add_option("--runs-max", o->runs_max, "Live runs at once")->capture_default_str()->check(CLI::Range(1, 64));
  cmd->callback([o, &exit_code] {
    exit_code = guarded([&] {
      return views::serve(*o, [&](int port) {
        fmt::print("swarmcheck serve: http://{}:{}/ (Ctrl-C stops)\n", o->bind, port);
        std::fflush(stdout);
      });
    });
  });
}

}  // namespace swarmcheck::cli
