// `swarmcheck dse` end to end: the thesis's DSE and its report, byte-identical files whatever the
// threads, ranks or interruptions, SIGINT, and bad input (exit 2, the JSON path, nothing written).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "tests/util/shell.hpp"

namespace fs = std::filesystem;

namespace {

const std::string kBin = SWARMCHECK_BIN;
const std::string kSource = SWARMCHECK_SOURCE_DIR;
const std::string kThesis = kSource + "/scenarios/thesis/dse/ertu.dse.json --scenario " + kSource + "/scenarios/thesis/dse/base.json";

swarmcheck::testing::ShellResult sh(const std::string& args) { return swarmcheck::testing::run_binary(kBin, args); }

fs::path temp_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("swarmcheck-dse-cli-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

std::string write(const fs::path& p, const std::string& text) {
  std::ofstream(p) << text;
  return p.string();
}

std::size_t lines(const fs::path& p) {
  const std::string t = read(p);
  return static_cast<std::size_t>(std::count(t.begin(), t.end(), '\n'));
}

// ~60 stochastic cosim points of the default scenario: a few seconds on one thread.
std::string slow_config(const fs::path& dir) {
  return write(dir / "slow.dse.json", R"({"parameters": {"ertu_perc": [0.05, 0.1, 0.2, 0.4], "seed": [1, 2, 3, 4, 5],
      "rule": ["deterministic", "stochastic", "thesis"]},
    "objectiveDefinitions": {"internalFunctions": {"done": {"columnID": "completion_step", "objectiveType": "max"},
      "travel": {"columnID": "distance", "objectiveType": "max"}, "turn": {"columnID": "turning", "objectiveType": "max"}}},
    "ranking": {"pareto": {"done": "-", "travel": "-"}}})");
}

// Starts the binary in the background; stdout and stderr go to files in `dir`.
pid_t spawn(const std::string& args, const fs::path& dir) {
  const std::string cmd = "exec " + kBin + " " + args + " >" + (dir / "out.txt").string() + " 2>" + (dir / "err.txt").string();
  const pid_t pid = fork();
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  return pid;
}

void wait_for_lines(const fs::path& file, std::size_t n) {
  for (int k = 0; k < 3000 && (!fs::exists(file) || lines(file) < n); ++k) std::this_thread::sleep_for(std::chrono::milliseconds(5));
}

// mpirun -n 3, allowed as root; sanitizer builds ignore Open MPI's own leaks at exit.
std::string mpirun_prefix() {
  return "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 ASAN_OPTIONS=detect_leaks=0 " + std::string(SWARMCHECK_MPIEXEC) +
         " -x ASAN_OPTIONS --oversubscribe -n 3 ";
}

const char* const kFiles[] = {"results.csv", "results.json", "report.html", "report.svg"};

}  // namespace

TEST(DseVerb, TheThesisDseGivesItsResultsAndTheReportNamesTheParetoFront) {
  const fs::path d = temp_dir("thesis");
  const auto r = sh("dse " + kThesis + " -o " + d.string());
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(read(d / "results.csv"),
            "point,{Environment}.EnvironmentInstance.ertu_perc,explorationPercentage,simulationTime,runs,status,rank,pareto_front\n"
            "1,0.07,31.25,3582,1,ok,7,false\n2,0.06,31.25,3582,1,ok,7,false\n3,0.05,100,2556,1,ok,4,false\n"
            "4,0.04,100,3528,1,ok,6,false\n5,0.03,100,1782,1,ok,3,false\n6,0.02,100,1404,1,ok,1,true\n"
            "7,0.01,100,2592,1,ok,5,false\n8,0.009,100,1494,1,ok,2,false\n");
  const std::string html = read(d / "report.html");
  EXPECT_NE(html.find("<h2>Pareto front (1 point)</h2>"), std::string::npos);
  EXPECT_NE(html.find("<p id=\"front\">point 6 (ertu_perc=0.02)</p>"), std::string::npos);
  EXPECT_NE(html.find("<svg"), std::string::npos);
  EXPECT_EQ(html.find("http://"), html.find("http://www.w3.org/2000/svg"));   // nothing fetched
  EXPECT_EQ(read(d / "report.svg").rfind("<svg", 0), 0u);
  EXPECT_EQ(nlohmann::json::parse(read(d / "results.json")).at("pareto_front"), nlohmann::json::array({6}));
  EXPECT_NE(r.out.find("Pareto front (1 point): point 6 (ertu_perc=0.02)"), std::string::npos);
  const auto j = sh("dse " + kThesis + " -o " + d.string() + " --json");
  ASSERT_EQ(j.status, 0);
  EXPECT_EQ(nlohmann::json::parse(j.out), nlohmann::json::parse(read(d / "results.json")));
}

TEST(DseVerb, OneThreadAndTwoThreadsWriteTheSameBytes) {
  const fs::path d = temp_dir("threads");
  const std::string config = write(d / "c.dse.json", R"({"parameters": {"ertu": [0.05, 0.2], "nRobots": [4, 12],
      "obstacleDensity": [0, 0.1], "rule": ["stochastic"], "replicates": [3]},
    "parameterConstraints": ["nRobots < 12 or obstacleDensity == 0"],
    "objectiveDefinitions": {"internalFunctions": {"e": {"columnID": "eP", "objectiveType": "mean"},
      "steps": {"columnID": "completion_step", "objectiveType": "max"}}},
    "objectiveConstraints": ["e > 50"], "ranking": {"pareto": {"e": "+", "steps": "-"}}})");
  ASSERT_EQ(sh("dse " + config + " -o " + (d / "one").string() + " --threads 1").status, 0);
  ASSERT_EQ(sh("dse " + config + " -o " + (d / "two").string() + " --threads 2").status, 0);
  for (const char* f : kFiles) EXPECT_EQ(read(d / "one" / f), read(d / "two" / f)) << f;
  EXPECT_NE(read(d / "one" / "results.csv").find("excluded by parameterConstraints[0]"), std::string::npos);
}

TEST(DseVerb, AKilledSweepResumesAndWritesTheSameBytes) {
  const fs::path d = temp_dir("kill");
  const std::string config = slow_config(d);
  ASSERT_EQ(sh("dse " + config + " -o " + (d / "clean").string() + " --threads 2").status, 0);
  const pid_t pid = spawn("dse " + config + " -o " + (d / "killed").string() + " --threads 1", d);
  wait_for_lines(d / "killed" / "journal.jsonl", 3);
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the sweep finished before it could be killed";
  EXPECT_FALSE(fs::exists(d / "killed" / "results.csv"));
  std::ofstream(d / "killed" / "journal.jsonl", std::ios::app) << R"({"key":"0123456789abcdef","ru)";   // a torn write
  const auto r = sh("dse " + config + " -o " + (d / "killed").string() + " --threads 2");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(r.out.find(" 0 points from the journal"), std::string::npos) << r.out;
  for (const char* f : kFiles) EXPECT_EQ(read(d / "clean" / f), read(d / "killed" / f)) << f;
}

TEST(DseVerb, SigintFinishesThePointsInFlightKeepsThemAndExits130) {
  const fs::path d = temp_dir("sigint");
  const std::string config = slow_config(d);
  const pid_t pid = spawn("dse " + config + " -o " + (d / "out").string() + " --threads 2", d);
  wait_for_lines(d / "out" / "journal.jsonl", 2);
  kill(pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130) << read(d / "err.txt");
  EXPECT_FALSE(fs::exists(d / "out" / "results.csv"));
  const std::size_t kept = lines(d / "out" / "journal.jsonl");
  EXPECT_GE(kept, 2u);
  EXPECT_LT(kept, 60u);
  EXPECT_NE(read(d / "err.txt").find("Run the same command again"), std::string::npos);
  const auto r = sh("dse " + config + " -o " + (d / "out").string());
  ASSERT_EQ(r.status, 0);
  EXPECT_NE(r.out.find(std::to_string(kept) + " points from the journal"), std::string::npos) << r.out;
}

TEST(DseVerb, BadInputExitsTwoWithThePathAndWritesNothing) {
  const fs::path d = temp_dir("bad");
  const std::string ok_objectives = R"("objectiveDefinitions": {"internalFunctions": {"e": {"columnID": "eP", "objectiveType": "max"}}})";
  const std::pair<std::string, std::string> cases[] = {
      {"{not json", "c.json:1:3: not valid JSON"},
      {R"({"parameters": {"speed": [1]}, )" + ok_objectives + "}", "c.json: parameters[\"speed\"]: unknown parameter"},
      {R"({"parameters": {"a1": []}, )" + ok_objectives + "}", "c.json: parameters[\"a1\"]: expected a non-empty list"},
      {R"({"parameters": {"a1": [1]}, "parameterConstraints": ["a1 >"], )" + ok_objectives + "}",
       "c.json: parameterConstraints[0], column 5: expected a number, a name or '('"},
      {R"({"parameters": {"a1": [1]}, "objectiveConstraints": ["speed > 1"], )" + ok_objectives + "}",
       "c.json: objectiveConstraints[0], column 1: unknown name 'speed'"},
      {R"({"algorithm": {"type": "genetic", "maxGenerationsWithoutImprovement": 0}, "parameters": {"a1": [1]}, )" + ok_objectives + "}",
       "c.json: algorithm.maxGenerationsWithoutImprovement: expected an integer in [1, 1000], got 0"},
      {R"({"parameters": {"mode": ["cosim"], "step_size": [18]}, )" + ok_objectives + "}",
       "point mode=cosim, step_size=18: params.step_size: expected at most 0.5 s"},
  };
  for (const auto& [text, want] : cases) {
    const std::string config = write(d / "c.json", text);
    const auto r = sh("dse " + config + " -o " + (d / "out").string());
    EXPECT_EQ(r.status, 2) << text;
    EXPECT_NE(r.out.find(want), std::string::npos) << r.out;
    EXPECT_FALSE(fs::exists(d / "out")) << text;
  }
  const std::string config = write(d / "c.json", R"({"parameters": {"a1": [1]}, )" + ok_objectives + "}");
  const auto missing = sh("dse " + config + " --scenario " + (d / "none.json").string() + " -o " + (d / "out").string());
  EXPECT_EQ(missing.status, 2);
  EXPECT_FALSE(fs::exists(d / "out"));
}

TEST(DseVerb, MpiRanksWriteTheSameBytesAsOneThread) {
  if (std::string(SWARMCHECK_MPIEXEC).empty())
    GTEST_SKIP() << "Open MPI is not installed (libopenmpi-dev, openmpi-bin): skipping the mpirun test";
  const fs::path d = temp_dir("mpi");
  const std::string mpirun = mpirun_prefix() + kBin;
  const std::string genetic = write(d / "ga.dse.json", R"({"algorithm": {"type": "genetic", "initialPopulation": 4, "seed": 5,
      "maxGenerationsWithoutImprovement": 2}, "parameters": {"ertu": [0.01, 0.02, 0.05, 0.1, 0.2], "a1": [0.25, 0.5, 1]},
    "objectiveDefinitions": {"internalFunctions": {"t": {"columnID": "sTime", "objectiveType": "max"}}},
    "ranking": {"pareto": {"t": "-"}}})");
  for (const std::string& config : {kThesis, slow_config(d), genetic}) {
    ASSERT_EQ(sh("dse " + config + " -o " + (d / "one").string() + " --threads 1").status, 0);
    const auto r = swarmcheck::testing::run_binary(mpirun, "dse " + config + " -o " + (d / "ranks").string());
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find("3 MPI ranks"), std::string::npos) << r.out;
    for (const char* f : kFiles) EXPECT_EQ(read(d / "one" / f), read(d / "ranks" / f)) << config << " " << f;
    fs::remove_all(d / "one");
    fs::remove_all(d / "ranks");
  }
}

TEST(ConformVerb, MpiRanksSplitTheCampaignIntoChunksAndAgree) {
  if (std::string(SWARMCHECK_MPIEXEC).empty())
    GTEST_SKIP() << "Open MPI is not installed (libopenmpi-dev, openmpi-bin): skipping the mpirun test";
  const fs::path d = temp_dir("conform");
  const std::string mpirun = mpirun_prefix() + kBin;
  const auto r = swarmcheck::testing::run_binary(mpirun, "conform --system exploration --cases 120 --seed 4 --json --out " + (d / "cx").string());
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j.at("agree").get<bool>());
  EXPECT_EQ(j.at("cases_run"), 120);
  EXPECT_EQ(j.at("mpi").at("chunks"), 3);    // 50 + 50 + 20
  EXPECT_EQ(j.at("mpi").at("ranks"), 3);
  EXPECT_FALSE(fs::exists(d / "cx"));         // nothing diverged, nothing written
}
