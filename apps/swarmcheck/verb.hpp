#pragma once
// How a verb is wired into the `swarmcheck` command line: each verb lives in its own file and
// exposes `void add_<name>_verb(CLI::App& app, int& exit_code)`, which registers a subcommand
// whose callback runs the verb inside guarded() and stores its exit status.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <functional>
#include <string>

#include "spec/util/input_error.hpp"

namespace swarmcheck::cli {

// Runs a verb body. Bad input (InputError) prints one line and gives exit status 2; any other
// exception is a bug in swarmcheck: it is reported as such with status 3, never a crash.
inline int guarded(const std::function<int()>& body) {
  try {
    return body();
  } catch (const InputError& e) {
    std::fprintf(stderr, "swarmcheck: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "swarmcheck: internal error (please report): %s\n", e.what());
    return 3;
  }
}

}  // namespace swarmcheck::cli
