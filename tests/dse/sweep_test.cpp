// Sweeps in-process: the thesis's DSE against an independent transliteration of the thesis's
// Environment, threads against one thread, the journal, and the genetic search.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "impl/dse/journal.hpp"
#include "impl/dse/results_io.hpp"
#include "impl/dse/sweep.hpp"
#include "spec/exploration/scenario.hpp"
#include "tests/dse/thesis_environment.hpp"

using namespace swarmcheck;
using namespace swarmcheck::dse;
namespace fs = std::filesystem;

namespace {

fs::path temp_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("swarmcheck-dse-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

struct Swept {
  SweepOutcome outcome;
  DseResults results;
};

Swept sweep(const DesignSpace& space, int32_t threads, const fs::path& dir) {
  ThreadExecutor ex(space, needed_columns(space.config()), threads, nullptr);
  Swept s;
  s.outcome = run_sweep(space, ex, SweepOptions{(dir / "journal.jsonl").string(), nullptr, nullptr});
  s.results = rank_outcomes(space, s.outcome.points);
  s.results.generations = s.outcome.generations;
  return s;
}

const std::string kSource = SWARMCHECK_SOURCE_DIR;

DseConfig sweep_config(const std::string& algorithm, const std::string& parameters, const std::string& extra = "") {
  return parse_dse_config(R"({"algorithm": )" + algorithm + R"(, "parameters": )" + parameters + extra +
                              R"(, "objectiveDefinitions": {"internalFunctions": {
                                   "e": {"columnID": "eP", "objectiveType": "mean"},
                                   "t": {"columnID": "completion_step", "objectiveType": "max"},
                                   "d": {"columnID": "distance", "objectiveType": "max"}}},
                                 "ranking": {"pareto": {"e": "+", "t": "-"}}})",
                          "c.json");
}

}  // namespace

TEST(ThesisDse, EveryPointGivesTheEpAndSTimeOfTheThesisEnvironmentCode) {
  const DseConfig c = load_dse_config(kSource + "/scenarios/thesis/dse/ertu.dse.json");
  const DesignSpace space(c, exploration::load_scenario(kSource + "/scenarios/thesis/dse/base.json"));
  check_design_space(space);
  const Swept s = sweep(space, 2, temp_dir("thesis"));
  ASSERT_EQ(s.results.points.size(), 8u);
  for (std::size_t i = 0; i < 8; ++i) {
    swarmcheck::testing::thesis::Setup t;
    t.robots = {{0.5, 0.5}, {9.5, 0.5}, {9.5, 9.5}, {0.5, 9.5}};
    t.obstacles = {{4, 4}, {4, 5}, {5, 4}, {5, 5}};
    t.step_size = 18;
    t.steps = 199;
    t.ertu_perc = c.parameters[0].values[i].number;
    const auto want = swarmcheck::testing::thesis::Environment(t).run();
    const PointResult& p = s.results.points[i];
    EXPECT_EQ(p.objectives[0].mean, want.eP) << "ertu " << t.ertu_perc;      // bit for bit
    EXPECT_EQ(p.objectives[1].mean, want.sTime) << "ertu " << t.ertu_perc;
  }
  // ertu * step_size >= 1 evaporates everything each step: the robots circle near their starts.
  EXPECT_EQ(s.results.points[0].objectives[0].mean, 31.25);
  ASSERT_EQ(s.results.front.size(), 1u);
  EXPECT_EQ(s.results.front[0], 5u);   // ertu 0.02: complete, fastest
  EXPECT_EQ(s.results.points[5].objectives[1].mean, 1404.0);
}

TEST(Sweep, ResultsAreIdenticalOnOneThreadAndOnSeveral) {
  const DseConfig c = sweep_config(R"({"type": "exhaustive"})",
                             R"({"ertu": [0.05, 0.2], "rule": ["deterministic", "stochastic"], "nRobots": [3, 6], "replicates": [3]})");
  exploration::Scenario base = exploration::default_scenario();
  base.mode = exploration::Mode::abstract;
  const DesignSpace space(c, base);
  const Swept one = sweep(space, 1, temp_dir("one"));
  const Swept two = sweep(space, 2, temp_dir("two"));
  EXPECT_EQ(one.outcome.runs, 8u * 3u);
  EXPECT_EQ(results_csv(space, one.results), results_csv(space, two.results));
  const ResultsContext ctx{"c.json", "default"};
  EXPECT_EQ(results_json(space, one.results, ctx), results_json(space, two.results, ctx));
  EXPECT_TRUE(one.results.points[0].objectives[0].ci95.has_value());
}

TEST(Sweep, ASecondRunReadsEveryPointFromTheJournalAndWritesTheSameResults) {
  const DseConfig c = sweep_config(R"({"type": "exhaustive"})", R"({"ertu": [0.05, 0.1, 0.2], "rule": ["stochastic"]})");
  exploration::Scenario base = exploration::default_scenario();
  base.mode = exploration::Mode::abstract;
  const DesignSpace space(c, base);
  const fs::path dir = temp_dir("journal");
  const Swept first = sweep(space, 2, dir);
  const Swept second = sweep(space, 2, dir);
  EXPECT_EQ(first.outcome.computed, 3u);
  EXPECT_EQ(second.outcome.computed, 0u);
  EXPECT_EQ(second.outcome.from_journal, 3u);
  EXPECT_EQ(results_csv(space, first.results), results_csv(space, second.results));
}

TEST(Journal, ATornLastLineIsSkippedAndTheNextLineStartsClean) {
  const fs::path dir = temp_dir("torn");
  const std::string path = (dir / "journal.jsonl").string();
  PointRuns p;
  p.key = "00000000000000aa";
  p.runs.push_back(RunOutputs{5, 10, 10, {{"eP", Aggregate{1, 2, 1.5}}}});
  {
    Journal j(path);
    j.append(p, "a1=1");
  }
  std::ofstream(path, std::ios::app) << R"({"key":"00000000000000bb","runs":[{"se)";   // cut by a crash
  PointRuns q = p;
  q.key = "00000000000000cc";
  {
    Journal j(path);
    EXPECT_EQ(j.entries(), 1u);
    EXPECT_EQ(j.skipped_lines(), 1u);
    j.append(q, "a1=2");
  }
  const Journal j(path);
  EXPECT_EQ(j.entries(), 2u);
  ASSERT_NE(j.find("00000000000000cc"), nullptr);
  EXPECT_EQ(j.find("00000000000000aa")->runs[0].columns[0].second.mean, 1.5);
  EXPECT_EQ(j.find("00000000000000bb"), nullptr);
}

TEST(Genetic, SeededSearchVisitsDistinctFeasiblePointsAndRepeatsOnOtherThreadCounts) {
  const DseConfig c = sweep_config(R"({"type": "genetic", "initialPopulation": 4, "mutationProbability": 30,
                                 "maxGenerationsWithoutImprovement": 2, "maxGenerations": 6, "seed": 3})",
                             R"({"ertu": [0.02, 0.05, 0.1, 0.2, 0.4], "a1": [0.25, 0.5, 1], "rule": ["deterministic", "stochastic"]})",
                             R"~(, "parameterConstraints": ["not (a1 == 1 and ertu == 0.4)"])~");
  exploration::Scenario base = exploration::default_scenario();
  base.mode = exploration::Mode::abstract;
  const DesignSpace space(c, base);
  const Swept a = sweep(space, 1, temp_dir("ga1"));
  const Swept b = sweep(space, 2, temp_dir("ga2"));
  EXPECT_EQ(results_csv(space, a.results), results_csv(space, b.results));
  EXPECT_GE(a.results.generations, 1);
  EXPECT_LE(a.results.generations, 6);
  std::set<Genome> seen;
  for (const PointResult& p : a.results.points) {
    EXPECT_TRUE(seen.insert(p.genome).second) << "a point was evaluated twice";
    EXPECT_EQ(space.violated_parameter_constraint(p.genome), -1);
  }
  EXPECT_GE(a.results.points.size(), 4u);
  EXPECT_FALSE(a.results.front.empty());
}
