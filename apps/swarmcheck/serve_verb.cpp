// swarmcheck serve: the live page and the editor over HTTP on loopback (views/server.hpp has the
// routes and the limits, views/request_policy.hpp who may ask). Runs until Ctrl-C (SIGINT) or
// SIGTERM.
#include "apps/swarmcheck/serve_verb.hpp"

#include <fmt/core.h>

#include <chrono>

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
  cmd->add_option("--runs-per-client", o->runs_per_client, "Live runs at once of one client address")
      ->capture_default_str()
      ->check(CLI::Range(1, 64));
  cmd->add_option("--allow-host", o->allowed_hosts,
                  "A name this server may be reached by (the Host header, without port), besides loopback names and the "
                  "bound address; repeat for several")
      ->type_name("NAME");
  cmd->add_option_function<double>(
         "--request-timeout",
         [o](double s) { o->request_timeout = std::chrono::milliseconds(static_cast<int64_t>(s * 1000)); },
         "Seconds a client has to send a request's head, and its body (plus a second per MiB) (default 10)")
      ->check(CLI::Range(0.1, 3600.0))
      ->type_name("S");
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
