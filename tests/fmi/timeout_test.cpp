// An FMU whose step never returns (the thesis's Environment waiting for a live-view client) stops
// `swarmcheck cosim` at --step-timeout with status 1, naming the instance and the step: every
// FMU freed, every unpacked folder removed, no output written. Shown on the test FMU
// (test_fmu/test_fmu.c): blocking in a system call, and blocking with every signal blocked (the
// process then ends from the watching thread, its folders removed).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "tests/fmi/scratch.hpp"
#include "tests/fmi/test_fmu.hpp"
#include "tests/util/shell.hpp"

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

struct BlockedRun {
  int status = 0;
  std::string out;
  std::string trace;   // the test FMU's instantiate / free lines
  bool tmp_empty = false;
  bool output_exists = false;
};

// Two instances of the test FMU, the first blocking in its third step; cosim with a 0.5 s limit.
BlockedRun run_blocking(const std::string& name, bool block_signals) {
  const fs::path dir = swarmcheck::testing::fmi_scratch("timeout-" + name);
  const fs::path tmp = dir / "tmp";
  fs::create_directories(tmp);
  swarmcheck::testing::write_test_fmu(dir, "t.fmu", swarmcheck::testing::TestFmu{false, false, true});
  Json mm;
  mm["fmus"] = {{"{Stuck}", "t.fmu"}, {"{Fine}", "t.fmu"}};
  mm["connections"] = {{"{Stuck}.stuck.y", {"{Fine}.fine.u"}}};
  mm["parameters"] = {{"{Stuck}.stuck.blockAtStep", 3}, {"{Stuck}.stuck.blockSignals", block_signals ? 1 : 0}};
  std::ofstream(dir / "mm.json") << mm.dump();
  const auto r = swarmcheck::testing::run_binary(
      "TMPDIR=" + tmp.string() + " SWARMCHECK_TEST_FMU_TRACE=" + (dir / "trace.txt").string() + " " + SWARMCHECK_BIN,
      "cosim " + (dir / "mm.json").string() + " --step-timeout 0.5 -o " + (dir / "outputs.csv").string());
  BlockedRun out{r.status, r.out, "", fs::is_empty(tmp), fs::exists(dir / "outputs.csv")};
  std::ifstream trace(dir / "trace.txt");
  out.trace.assign(std::istreambuf_iterator<char>(trace), {});
  // Nothing else in the folder: no temporary file of outputs.csv.
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string f = e.path().filename().string();
    EXPECT_TRUE(f == "tmp" || f == "t.fmu" || f == "mm.json" || f == "trace.txt") << "left behind: " << f;
  }
  fs::remove_all(dir);
  return out;
}

}  // namespace

TEST(FmiStepTimeout, AStepThatNeverReturnsStopsTheRunWithStatusOneNamingInstanceAndStepEveryFmuFreed) {
  const BlockedRun r = run_blocking("pause", false);
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_NE(r.out.find("swarmcheck cosim: {Stuck}.stuck ("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("fmi2DoStep at step 3 (t = 0.20000000000000001 s) did not return within 0.5 s"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("(--step-timeout): run stopped, FMUs freed"), std::string::npos) << r.out;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  // Both instances were made and both freed, the stuck one included.
  EXPECT_EQ(r.trace, "instantiate {Stuck}.stuck\ninstantiate {Fine}.fine\nfree {Stuck}.stuck\nfree {Fine}.fine\n");
  EXPECT_TRUE(r.tmp_empty);
  EXPECT_FALSE(r.output_exists);
}

TEST(FmiStepTimeout, AStepThatBlocksEverySignalStillEndsTheProcessWithStatusOneAndItsFoldersRemoved) {
  const BlockedRun r = run_blocking("masked", true);
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_NE(r.out.find("{Stuck}.stuck ("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("fmi2DoStep at step 3"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("could not be interrupted (it blocks signals)"), std::string::npos) << r.out;
  EXPECT_EQ(r.trace, "instantiate {Stuck}.stuck\ninstantiate {Fine}.fine\n");   // not freed: the process ended
  EXPECT_TRUE(r.tmp_empty);
  EXPECT_FALSE(r.output_exists);
}
