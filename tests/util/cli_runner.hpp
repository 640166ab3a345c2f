#pragma once
// Running one verb in-process, wired into CLI11 exactly as main.cpp does, with stdout and stderr
// captured: CliRun r = run_verb(swarmcheck::cli::add_fsm_verb, {"fsm", "check", "a.fsm"});
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace swarmcheck::testing {

struct CliRun {
  int status = -1;
  std::string out, err;
};

inline CliRun run_verb(void (*add_verb)(CLI::App&, int&), const std::vector<std::string>& args) {
  CLI::App app{"swarmcheck"};
  app.require_subcommand(1);
  int exit_code = 0;
  add_verb(app, exit_code);
  std::vector<const char*> argv{"swarmcheck"};
  for (const auto& a : args) argv.push_back(a.c_str());
  CliRun r;
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
    r.status = exit_code;
  } catch (const CLI::ParseError& e) {
    r.status = app.exit(e) == 0 ? 0 : 2;
  }
  r.out = ::testing::internal::GetCapturedStdout();
  r.err = ::testing::internal::GetCapturedStderr();
  return r;
}

}  // namespace swarmcheck::testing
