// `swarmcheck mission plan|run` driven through CLI11 exactly as main.cpp wires it
// (add_mission_verb), with stdout captured: the acceptance answers, statuses, trace files.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "apps/swarmcheck/mission_verb.hpp"
#include "tests/util/cli_runner.hpp"

namespace {

namespace fs = std::filesystem;
const std::string kMission = SWARMCHECK_SCENARIOS "/thesis/thesis-mission.json";

using swarmcheck::testing::CliRun;

CliRun run_cli(const std::vector<std::string>& args) {
  return swarmcheck::testing::run_verb(swarmcheck::cli::add_mission_verb, args);
}

fs::path temp_dir() {
  const fs::path d =
      fs::temp_directory_path() / ("swarmcheck_mission_cli_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

std::vector<std::string> tasks_of(const nlohmann::json& plan, const std::string& robot) {
  for (const auto& r : plan["robots"])
    if (r["name"] == robot) return r["tasks"].get<std::vector<std::string>>();
  return {};
}

TEST(MissionCli, ThesisPlanGivesATasks3Then4AndBTasks1Then2) {
  const CliRun r = run_cli({"mission", "plan", kMission, "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(tasks_of(j, "A"), (std::vector<std::string>{"tsk3", "tsk4"}));
  EXPECT_EQ(tasks_of(j, "B"), (std::vector<std::string>{"tsk1", "tsk2"}));
  EXPECT_EQ(j["final_state"], "s134:146:143");
  EXPECT_NEAR(j["makespan"].get<double>(), 33.6, 0.05);  // the thesis: 33.6 m
}

TEST(MissionCli, PlanFromAStateUsesThatState) {
  const CliRun r = run_cli({"mission", "plan", kMission, "--from", "s134:146:143", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["events"].empty());
  EXPECT_EQ(j["makespan"], 0.0);
}

TEST(MissionCli, PlanFromAnUnknownStateIsBadInput) {
  const CliRun r = run_cli({"mission", "plan", kMission, "--from", "nowhere"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--from: state \"nowhere\" is not in control2.fsm"), std::string::npos)
      << r.err;
  EXPECT_TRUE(r.out.empty());
}

TEST(MissionCli, ThesisPlannerIsSelectable) {
  const CliRun r = run_cli({"mission", "plan", kMission, "--planner", "thesis", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["planner"], "thesis");
  EXPECT_EQ(j["final_state"], "s134:146:143");
}

TEST(MissionCli, MissingMissionFileIsBadInput) {
  const CliRun r = run_cli({"mission", "plan", "/nonexistent/m.json"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("/nonexistent/m.json: cannot open the mission file"), std::string::npos);
}

TEST(MissionCli, RunKinematicCompletesAndWritesTheTrace) {
  const fs::path trace = temp_dir() / "run.jsonl";
  const CliRun r = run_cli({"mission", "run", kMission, "--body", "kinematic", "--json",
                            "--trace", trace.string()});
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["completed"], true);
  EXPECT_EQ(j["final_state"], "s134:146:143");
  EXPECT_NEAR(j["makespan_planned"].get<double>(), 33.6, 0.05);
  EXPECT_TRUE(j["travel"].contains("A"));
  EXPECT_GT(j["events"].size(), 10u);
  EXPECT_TRUE(fs::exists(trace));
  std::ifstream in(trace);
  std::string first;
  std::getline(in, first);
  EXPECT_EQ(nlohmann::json::parse(first)["format"], "swarmcheck-mission-trace");
}

TEST(MissionCli, RunToAnUnwritableTraceIsBadInputAndWritesNothing) {
  const CliRun r = run_cli({"mission", "run", kMission, "--body", "kinematic", "--trace",
                            "/nonexistent-dir/t.jsonl"});
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty());
}

}  // namespace
