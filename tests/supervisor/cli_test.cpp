// `swarmcheck fsm ...` driven through CLI11 exactly as main.cpp wires it (add_fsm_verb), with
// stdout captured: the acceptance line, exit statuses, and files written whole.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "apps/swarmcheck/fsm_verb.hpp"
#include "tests/util/cli_runner.hpp"
#include "impl/supervisor/fsm_io.hpp"

namespace {

namespace fs = std::filesystem;
const std::string kThesis = SWARMCHECK_SCENARIOS "/thesis";

using swarmcheck::testing::CliRun;

CliRun run_cli(const std::vector<std::string>& args) {
  return swarmcheck::testing::run_verb(swarmcheck::cli::add_fsm_verb, args);
}

fs::path temp_dir() {
  const fs::path d = fs::temp_directory_path() / ("swarmcheck_cli_test_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

TEST(FsmCli, CheckThesisSupervisorJson) {
  const CliRun r = run_cli({"fsm", "check", kThesis + "/control2.fsm", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["states"], 72);
  EXPECT_EQ(j["nonblocking"], true);
  EXPECT_EQ(j["accessible"], true);
  EXPECT_EQ(j["deterministic"], true);
  EXPECT_EQ(j["initial"], "s1");
  EXPECT_TRUE(j["blocking_states"].empty());
}

TEST(FsmCli, CheckEnginesAgree) {
  const CliRun a = run_cli({"fsm", "check", kThesis + "/control2.fsm", "--json"});
  const CliRun b = run_cli({"fsm", "check", kThesis + "/control2.fsm", "--json", "--engine", "model"});
  EXPECT_EQ(a.out, b.out);
}

TEST(FsmCli, CheckListsBlockingStatesAndExitsOne) {
  const fs::path f = temp_dir() / "blocking.fsm";
  std::ofstream(f) << "3\ns1 0 2\na s2\nb s3\ns2 1 0\ns3 0 0\n";
  const CliRun r = run_cli({"fsm", "check", f.string(), "--json"});
  EXPECT_EQ(r.status, 1);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["nonblocking"], false);
  EXPECT_EQ(j["blocking_states"], nlohmann::json::array({"s3"}));
}

TEST(FsmCli, BadFileIsStatusTwoWithWhereAndWhat) {
  const fs::path f = temp_dir() / "bad.fsm";
  std::ofstream(f) << "1\ns1 0 1\na s9 c o\n";
  const CliRun r = run_cli({"fsm", "check", f.string()});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "swarmcheck: error: " + f.string() +
                       ":3:3: transition target 's9' of state 's1' is not a state (no block of "
                       "that name in this file)\n");
  EXPECT_EQ(r.out, "");
}

TEST(FsmCli, ProductWritesAFileThatReadsBack) {
  const fs::path d = temp_dir();
  std::ofstream(d / "a.fsm") << "2\nx 1 1\na y c o\ny 0 1\nb x uc o\n";
  std::ofstream(d / "b.fsm") << "1\np 1 1\nb p uc o\n";
  const CliRun r = run_cli({"fsm", "product", (d / "a.fsm").string(), (d / "b.fsm").string(), "-o",
                     (d / "ab.fsm").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto ab = swarmcheck::impl::supervisor::read_fsm_file((d / "ab.fsm").string());
  EXPECT_EQ(ab.states, (std::vector<std::string>{"x.p", "y.p"}));
}

TEST(FsmCli, ExportToDotAndJson) {
  const CliRun dot = run_cli({"fsm", "export", kThesis + "/control2.fsm", "--to", "dot"});
  ASSERT_EQ(dot.status, 0);
  EXPECT_EQ(dot.out.rfind("digraph fsm {", 0), 0u);
  EXPECT_NE(dot.out.find("\"s134:146:143\" [shape=doublecircle];"), std::string::npos);
  const CliRun json = run_cli({"fsm", "export", kThesis + "/control2.fsm", "--to", "json"});
  ASSERT_EQ(json.status, 0);
  EXPECT_EQ(nlohmann::json::parse(json.out)["states"].size(), 72u);
}

TEST(FsmCli, CompareGivesTheShortestWitnessesOnBothEnginesAndExitsOneWhenNotEqual) {
  const std::vector<std::string> args{"fsm", "compare", kThesis + "/supervisor_any_robot.fsm",
                                      kThesis + "/control2.fsm", "--json"};
  const CliRun r = run_cli(args);
  ASSERT_EQ(r.status, 1) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["a_in_b"]["closed_witness"],
            nlohmann::json({"a5e", "b8e", "a3s", "a6e", "a3f", "a4s", "a4f"}));
  EXPECT_EQ(j["b_in_a"]["closed_witness"],
            nlohmann::json({"a5e", "b8e", "a3s", "a6e", "a3f", "a4s", "a5e"}));
  auto with_model = args;
  with_model.insert(with_model.end(), {"--engine", "model"});
  EXPECT_EQ(run_cli(with_model).out, r.out);
}

TEST(FsmCli, CompareOfAFileWithItselfIsEqual) {
  const CliRun r = run_cli({"fsm", "compare", kThesis + "/control2.fsm", kThesis + "/control2.fsm"});
  EXPECT_EQ(r.status, 0) << r.err;
}

TEST(FsmCli, UnknownFormatIsAUsageError) {
  const CliRun r = run_cli({"fsm", "export", kThesis + "/control2.fsm", "--to", "png"});
  EXPECT_EQ(r.status, 2);
}

}  // namespace
