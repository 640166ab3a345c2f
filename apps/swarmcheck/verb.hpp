#pragma once
// How a verb is wired into the `swarmcheck` command line: each verb lives in its own file and
// exposes `void add_<name>_verb(CLI::App& app, int& exit_code)`, which registers a subcommand
// whose callback runs the verb inside guarded() and stores its exit status.
#include <CLI/CLI.hpp>
#include <charconv>
#include <cstdint>
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

// A seed is a decimal integer in [0, 2^64 - 1], as written: CLI11 alone would wrap -1 and clamp
// 99999999999999999999 to 2^64 - 1, silently running another seed than the one asked for.
inline CLI::Validator seed_validator() {
  return CLI::Validator(
      [](const std::string& text) -> std::string {
        uint64_t value = 0;
        const char* end = text.data() + text.size();
        const auto [ptr, ec] = std::from_chars(text.data(), end, value);
        if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos || ec != std::errc() || ptr != end)
          return "expected an integer in [0, 18446744073709551615], got " + text;
        return {};
      },
      "SEED");
}

}  // namespace swarmcheck::cli
