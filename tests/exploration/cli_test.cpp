// `swarmcheck run` end to end: the summary, the trace, and every bad input (exit status 2, one
// message, no trace file left behind).
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
  fs::path d = fs::temp_directory_path() / ("swarmcheck-cli-" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

std::string write(const fs::path& p, const std::string& text) {
  std::ofstream(p) << text;
  return p.string();
}

}  // namespace

TEST(RunVerb, JsonSummaryOfTheDefaultScenarioInAbstractMode) {
  const Result r = sh("run --mode abstract --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j.at("completed").get<bool>());
  EXPECT_EQ(j.at("completion_step"), j.at("steps"));
  EXPECT_EQ(j.at("eP").get<double>(), 100.0);
  EXPECT_EQ(j.at("visited"), 96);
  EXPECT_EQ(j.at("free_cells"), 96);
  EXPECT_TRUE(j.contains("sTime"));
}

TEST(RunVerb, IncompleteRunReportsNullCompletionStep) {
  const Result r = sh("run --mode abstract --steps 3 --json");
  ASSERT_EQ(r.status, 1) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j.at("completed").get<bool>());
  EXPECT_TRUE(j.at("completion_step").is_null());
  EXPECT_EQ(j.at("steps"), 3);
}

TEST(RunVerb, TraceIsAHeaderThenOneRecordPerStepAndRepeatsByteForByte) {
  const fs::path d = temp_dir();
  const std::string a = (d / "a.jsonl").string(), b = (d / "b.jsonl").string();
  ASSERT_EQ(sh("run --rule stochastic --seed 9 --steps 500 --trace " + a).status, 1);
  ASSERT_EQ(sh("run --rule stochastic --seed 9 --steps 500 --trace " + b).status, 1);
  std::ifstream fa(a), fb(b);
  const std::string ta((std::istreambuf_iterator<char>(fa)), {}), tb((std::istreambuf_iterator<char>(fb)), {});
  EXPECT_EQ(ta, tb);
  std::istringstream lines(ta);
  std::string header;
  std::getline(lines, header);
  const auto h = nlohmann::json::parse(header);
  EXPECT_EQ(h.at("format"), "swarmcheck-trace");
  EXPECT_EQ(h.at("rule"), "stochastic");
  int records = 0;
  for (std::string l; std::getline(lines, l);) ++records;
  EXPECT_EQ(records, 501);   // steps 0..500
  fs::remove_all(d);
}

TEST(RunVerb, BadInputsExitTwoWithOneMessageAndLeaveNoTrace) {
  const fs::path d = temp_dir();
  const std::string trace = (d / "t.jsonl").string();
  const std::pair<std::string, std::string> cases[] = {
      {"{not json", "not valid JSON"},
      {R"({"map_size": 4, "robots": [[0.5, 0.5]], "extra": 1})", "extra: unknown key"},
      {R"({"map_size": 4, "robots": [[0.5, "a"]]})", "robots[0][1]: expected a number, got a string"},
      {R"({"map_size": 0, "robots": [[0.5, 0.5]]})", "map_size: expected an integer in [1, 65536]"},
      {R"({"map_size": 4, "robots": [[9, 0.5]]})", "robots[0]: expected a position"},
      {R"({"map_size": 4, "robots": [[0.5, 0.5]], "obstacles": [[0, 0]]})", "which is obstacles[0]"},
      {R"({"map_size": 4, "robots": [[0.5, 0.5], [0.7, 0.2]]})", "already taken by robots[0]"},
      {R"({"map_size": 4, "robots": [[0.5, 0.5]], "params": {"eta": 0}})", "params.eta: expected a finite number > 0"},
      // positions and times that would overflow to infinity in the trace
      {R"({"map_size": 10, "cell_size": 1e308, "robots": [[1e308, 0]]})", "cell_size: expected a number in (0, 1e6] (metres)"},
      {R"({"map_size": 4, "robots": [[0.5, 0.5]], "mode": "abstract", "params": {"step_size": 1e308}})",
       "params.step_size: expected a number in (0, 1e6] (seconds)"},
  };
  int k = 0;
  for (const auto& [text, expected] : cases) {
    const std::string file = write(d / ("bad" + std::to_string(k++) + ".json"), text);
    const Result r = sh("run " + file + " --trace " + trace);
    EXPECT_EQ(r.status, 2) << text;
    EXPECT_NE(r.out.find(expected), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(file), std::string::npos) << "the message names the file: " << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << "one message: " << r.out;
    EXPECT_FALSE(fs::exists(trace));
  }
  EXPECT_EQ(sh("run --rule greedy").status, 2);
  EXPECT_EQ(sh("run /nonexistent.json").status, 2);
  EXPECT_EQ(sh("run --steps -4").status, 2);
  const Result unwritable = sh("run --steps 2 --trace /nonexistent-dir/t.jsonl");
  EXPECT_EQ(unwritable.status, 2);
  EXPECT_NE(unwritable.out.find("cannot write"), std::string::npos);
  fs::remove_all(d);
}

TEST(RunVerb, OverridesAreValidatedToo) {
  const fs::path d = temp_dir();
  const std::string file = write(d / "slow.json", R"({"map_size": 4, "robots": [[0.5, 0.5]], "mode": "abstract", "params": {"step_size": 1}})");
  EXPECT_EQ(sh("run " + file + " --json").status, 0);
  const Result r = sh("run " + file + " --mode cosim");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find(file + " with the command-line overrides: params.step_size: expected at most 0.5 s in cosim mode"),
            std::string::npos) << r.out;
  // The cells are checked on loading, before any override.
  const std::string taken = write(d / "taken.json", R"({"map_size": 4, "robots": [[0.5, 0.5], [0.7, 0.2]]})");
  const Result t = sh("run " + taken + " --mode cosim");
  EXPECT_EQ(t.status, 2);
  EXPECT_NE(t.out.find(taken + ": robots[1]: starts in cell [0, 0], already taken by robots[0]"), std::string::npos) << t.out;
  fs::remove_all(d);
}

// Enough robots for the parallel stages (robots x window cells >= 2^15): the trace is the same
// bytes on one thread, on two, on three, and with the thread count from the environment.
TEST(RunVerb, ThreadsFlagAndEnvironmentGiveTheSameTraceBytesAsOneThread) {
  const fs::path d = temp_dir();
  std::string robots;
  for (int k = 0; k < 4000; ++k)
    robots += (k ? ", [" : "[") + std::to_string(4 * k / 128) + ".5, " + std::to_string(4 * k % 128) + ".5]";
  const std::string file = write(d / "crowd.json", R"({"map_size": 128, "mode": "abstract", "rule": "stochastic",
      "max_steps": 30, "robots": [)" + robots + "]}");
  const auto trace = [&](const std::string& prefix, const std::string& flags, const std::string& name) {
    const std::string out = (d / name).string();
    const Result r = swarmcheck::testing::run_binary(prefix + SWARMCHECK_BIN, "run " + file + flags + " --trace " + out);
    EXPECT_EQ(r.status, 1) << r.out;   // 30 steps do not complete the map
    std::ifstream in(out, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string one = trace("", " --threads 1", "t1.jsonl");
  ASSERT_GT(one.size(), 1000u);
  EXPECT_EQ(trace("", " --threads 2", "t2.jsonl"), one);
  EXPECT_EQ(trace("", " --threads 3", "t3.jsonl"), one);
  EXPECT_EQ(trace("SWARMCHECK_THREADS=2 ", "", "env.jsonl"), one);
  const Result bad = swarmcheck::testing::run_binary(std::string("SWARMCHECK_THREADS=many ") + SWARMCHECK_BIN, "run --steps 2");
  EXPECT_EQ(bad.status, 2) << bad.out;
  EXPECT_NE(bad.out.find("--threads"), std::string::npos) << bad.out;
  fs::remove_all(d);
}
