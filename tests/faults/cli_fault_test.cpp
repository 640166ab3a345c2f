// `swarmcheck conform` on a library that crashes and on one that hangs (the binary linked with a
// variant of the catalogue, tests/faults/CMakeLists.txt): each is a counterexample, shrunk and
// written like any other, with status 1; never the signal's status (139) and never stuck.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "tests/util/shell.hpp"

namespace fs = std::filesystem;
using swarmcheck::testing::run_binary;

namespace {

fs::path temp_dir(const std::string& name) {
  fs::path d = fs::temp_directory_path() / ("swarmcheck-fault-cli-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(d);
  return d;
}

}  // namespace

TEST(ConformOnACrashingLibrary, AutomataCampaignEndsWithStatusOneAndTheMinimalInputsThatCrashIt) {
  const fs::path d = temp_dir("crash");
  const auto r = run_binary(SWARMCHECK_CRASHING_BIN, "conform --system automata --json --out " + d.string());
  ASSERT_EQ(r.status, 1) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j.at("agree").get<bool>());
  const auto& cx = j.at("counterexample");
  const std::string difference = cx.at("difference").get<std::string>();
  EXPECT_EQ(difference.rfind("impl crashed with SIGSEGV", 0), 0u) << difference;
  EXPECT_EQ(cx.at("kind"), "inclusion");
  EXPECT_LE(cx.at("states").get<int>(), 6);   // shrunk: a few states in all
  for (const auto& f : cx.at("files")) EXPECT_TRUE(fs::exists(f.get<std::string>())) << f;
  // The text report says the same, and how to show it again.
  const auto text = run_binary(SWARMCHECK_CRASHING_BIN, "conform --system automata --out " + d.string());
  EXPECT_EQ(text.status, 1) << text.out;
  EXPECT_NE(text.out.find("conform automata: DIFFERENCE after"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("impl crashed with SIGSEGV"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("show: swarmcheck fsm compare"), std::string::npos) << text.out;
  fs::remove_all(d);
}

TEST(ConformOnAHangingLibrary, MissionCampaignStopsTheRunAtTheTimeLimitAndEndsWithStatusOne) {
  const fs::path d = temp_dir("hang");
  const auto r =
      run_binary(SWARMCHECK_HANGING_BIN, "conform --system missions --case-time-limit 2 --json --out " + d.string());
  ASSERT_EQ(r.status, 1) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  const auto& cx = j.at("counterexample");
  const std::string difference = cx.at("difference").get<std::string>();
  EXPECT_NE(difference.find("impl hung at step "), std::string::npos) << difference;
  EXPECT_NE(difference.find("(no progress for 2 s)"), std::string::npos) << difference;
  EXPECT_TRUE(fs::exists(cx.at("mission").get<std::string>()));
  EXPECT_TRUE(fs::exists(cx.at("fsm").get<std::string>()));
  EXPECT_NE(cx.at("command").get<std::string>().find("swarmcheck mission run "), std::string::npos);
  fs::remove_all(d);
}
