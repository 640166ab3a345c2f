// `swarmcheck conform` and `swarmcheck replay` on the command line.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/util/shell.hpp"

namespace fs = std::filesystem;

namespace {
using Result = swarmcheck::testing::ShellResult;

Result sh(const std::string& args) { return swarmcheck::testing::run_binary(SWARMCHECK_BIN, args); }

fs::path temp_dir() {
  fs::path d = fs::temp_directory_path() / ("swarmcheck-replay-" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}
}  // namespace

TEST(ReplayVerb, ARunTraceReproducesOnBothEnginesAndATamperedOneNamesTheField) {
  const fs::path d = temp_dir();
  const std::string trace = (d / "run.jsonl").string();
  ASSERT_EQ(sh("run --rule stochastic --steps 600 --trace " + trace).status, 1);   // 600 steps: not completed
  const Result on_impl = sh("replay " + trace);
  EXPECT_EQ(on_impl.status, 0) << on_impl.out;
  EXPECT_NE(on_impl.out.find("reproduces the trace (601 records agree bit for bit)"), std::string::npos) << on_impl.out;
  EXPECT_EQ(sh("replay " + trace + " --against model").status, 0);
  // Change robot 1's cell in the record of step 300.
  std::ifstream in(trace);
  std::ofstream out((d / "tampered.jsonl").string());
  std::string line;
  for (int k = 0; std::getline(in, line); ++k) {
    if (k == 301) {
      auto j = nlohmann::ordered_json::parse(line);
      j["robots"][1]["cell"][0] = j["robots"][1]["cell"][0].get<int>() + 1;
      line = j.dump();
    }
    out << line << '\n';
  }
  out.close();
  const Result tampered = sh("replay " + (d / "tampered.jsonl").string());
  EXPECT_EQ(tampered.status, 1);
  EXPECT_NE(tampered.out.find("step 300: robots[1].cell trace=("), std::string::npos) << tampered.out;
  fs::remove_all(d);
}

TEST(ReplayVerb, AMalformedTraceExitsTwoNamingFileAndLine) {
  const fs::path d = temp_dir();
  const std::string bad = (d / "bad.jsonl").string();
  std::ofstream(bad) << "{\"format\": \"swarmcheck-trace\", \"system\": \"exploration\", \"scenario\": {\"map_size\": 3, \"robots\": [[0.5, 0.5]]}}\n{\"step\": \"zero\"}\n";
  const Result r = sh("replay " + bad);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find(bad + ":2: expected a step record: step: expected an integer, got a string"), std::string::npos) << r.out;
  std::ofstream(bad) << "not a header\n";
  EXPECT_EQ(sh("replay " + bad).status, 2);
  fs::remove_all(d);
}

// The acceptance campaign (500 cases, seed 1) in the release build; a sanitizer build,
// some 40x slower, runs the first 60 of the same cases.
TEST(ConformVerb, AgreesOnTheAcceptanceCampaign) {
  const Result r = sh("conform --system exploration --cases " + std::to_string(SWARMCHECK_CONFORM_CASES) + " --seed 1 --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j.at("agree").get<bool>());
  EXPECT_EQ(j.at("cases_run"), SWARMCHECK_CONFORM_CASES);
}

TEST(ConformVerb, BadOptionsExitTwo) {
  EXPECT_EQ(sh("conform --cases 0").status, 2);
  EXPECT_EQ(sh("conform --cases many").status, 2);
  const Result limit = sh("conform --case-time-limit 0");
  EXPECT_EQ(limit.status, 2);
  EXPECT_NE(limit.out.find("--case-time-limit: expected seconds, at least 0.001 and at most 86400"), std::string::npos)
      << limit.out;
}
