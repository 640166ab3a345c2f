// Design points on a base scenario: the factorial order, replicate seeds, seeded placement,
// parameter constraints and the journal key.
#include <cstdlib>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <set>

#include "impl/dse/design_space.hpp"
#include "impl/dse/sweep.hpp"
#include "spec/exploration/scenario.hpp"
#include "spec/util/budget.hpp"

using namespace swarmcheck;
using namespace swarmcheck::dse;
using exploration::Scenario;

namespace {

// One seed for every run (an RC_PARAMS in the environment wins): CI and a developer see the
// same cases.
const bool kSeededDseDesignSpaceTest = [] { return ::setenv("RC_PARAMS", "seed=17", 0) == 0; }();

DseConfig config(const std::string& parameters, const std::string& constraints = "[]") {
  return parse_dse_config(R"({"parameters": )" + parameters + R"(, "parameterConstraints": )" + constraints +
                              R"(, "objectiveDefinitions": {"internalFunctions": {"e": {"columnID": "eP", "objectiveType": "max"}}}})",
                          "c.json");
}

}  // namespace

TEST(DesignSpace, TheFirstParameterVariesSlowest) {
  const DseConfig c = config(R"({"a1": [1, 2], "rule": ["thesis", "deterministic", "stochastic"]})");
  const DesignSpace space(c, exploration::default_scenario());
  EXPECT_EQ(space.size(), 6u);
  EXPECT_EQ(space.genome_of(0), (Genome{0, 0}));
  EXPECT_EQ(space.genome_of(2), (Genome{0, 2}));
  EXPECT_EQ(space.genome_of(3), (Genome{1, 0}));
  for (uint64_t i = 0; i < space.size(); ++i) EXPECT_EQ(space.index_of(space.genome_of(i)), i);
  const Scenario s = space.scenario(space.genome_of(5), 0);
  EXPECT_EQ(s.params.a1, 2.0);
  EXPECT_EQ(s.rule, exploration::RuleSet::stochastic);
  EXPECT_EQ(space.describe(space.genome_of(5)), "a1=2, rule=stochastic");
}

TEST(DesignSpace, ControllerAndBodyAreDesignParametersAndAnIntocpsBodyKeepsTheBaseParameters) {
  const DseConfig c = config(R"({"controller": ["swarmcheck", "thesis"], "body": ["kinematic", "intocps"]})");
  Scenario base = exploration::default_scenario();
  base.body.intocps.mu = 0.25;   // set in the base scenario's body, kept when a point chooses intocps
  const DesignSpace space(c, base);
  EXPECT_EQ(space.size(), 4u);
  const Scenario s = space.scenario(space.genome_of(3), 0);
  EXPECT_EQ(s.controller, exploration::ControllerKind::thesis);
  EXPECT_EQ(s.body.kind, exploration::BodyKind::intocps);
  EXPECT_EQ(s.body.intocps.mu, 0.25);
  EXPECT_EQ(space.scenario(space.genome_of(0), 0).body.kind, exploration::BodyKind::kinematic);
  EXPECT_EQ(space.describe(space.genome_of(3)), "controller=thesis, body=intocps");
}

TEST(DesignSpace, ReplicateZeroIsTheScenarioItselfAndOthersHaveDistinctSeeds) {
  const DseConfig c = config(R"({"replicates": [4], "seed": [7]})");
  const DesignSpace space(c, exploration::default_scenario());
  const Genome g{0, 0};
  EXPECT_EQ(space.replicates(g), 4);
  std::set<uint64_t> seeds;
  for (int32_t r = 0; r < 4; ++r) seeds.insert(space.scenario(g, r).seed);
  EXPECT_EQ(space.scenario(g, 0).seed, 7u);
  EXPECT_EQ(seeds.size(), 4u);
  EXPECT_EQ(space.scenario(g, 2).seed, replicate_seed(7, 2));
}

TEST(DesignSpace, ParameterConstraintsExcludePointsBeforeTheyRun) {
  const DseConfig c = config(R"({"a1": [0.5, 1, 2], "a2": [0.5, 1]})", R"(["a1 <= a2", "eta > 0.5"])");
  const DesignSpace space(c, exploration::default_scenario());
  EXPECT_EQ(space.violated_parameter_constraint(Genome{0, 0}), -1);
  EXPECT_EQ(space.violated_parameter_constraint(Genome{2, 1}), 0);   // a1 = 2 > a2 = 1
  EXPECT_EQ(space.knob_value(Genome{0, 0}, Knob::eta).number, 0.9);   // not swept: the base's
}

TEST(DesignSpace, BadCombinationsAreFoundBeforeAnythingRunsAndNameThePoint) {
  const DseConfig c = config(R"({"mode": ["abstract", "cosim"], "step_size": [0.1, 18]})");
  const DesignSpace space(c, exploration::default_scenario());
  try {
    check_design_space(space);
    FAIL() << "cosim with step_size 18 was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("point mode=cosim, step_size=18: params.step_size: expected at most 0.5 s"), std::string::npos) << e.what();
  }
  const DseConfig crowded = config(R"({"nRobots": [200], "mapSize": [10]})");
  EXPECT_THROW(check_design_space(DesignSpace(crowded, exploration::default_scenario())), InputError);
}

// The memory check adds up the points that may be in memory at once, largest first: a small point
// beside a large one fits where two large ones would not.
TEST(DesignSpace, TheMemoryCheckCountsTheLargestPointsThatRunAtOnce) {
  const std::uint64_t limit = std::uint64_t{1500} << 20;   // 1.5 GiB; an 8192^2 map needs 1 GiB
  const DseConfig one_large = config(R"({"mapSize": [64, 8192]})");
  EXPECT_NO_THROW(check_design_space(DesignSpace(one_large, exploration::default_scenario()), limit, 2));
  const DseConfig two_large = config(R"({"mapSize": [8190, 8192]})");
  EXPECT_NO_THROW(check_design_space(DesignSpace(two_large, exploration::default_scenario()), limit, 1));
  try {
    check_design_space(DesignSpace(two_large, exploration::default_scenario()), limit, 2);
    FAIL() << "two 1 GiB points at once were accepted under 1.5 GiB";
  } catch (const BudgetExceeded& e) {
    EXPECT_NE(std::string(e.what()).find("design point mapSize=8192: a 8192 x 8192 map with 4 robots, with the 2 largest "
                                         "points at once (--threads 2; --threads 1 runs one at a time) needs about 2.0 GiB"),
              std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(check_design_space(DesignSpace(two_large, exploration::default_scenario()), 0, 8));   // 0: no limit
}

TEST(DesignSpace, TheKeyChangesWithAnythingTheRunsDependOn) {
  const DseConfig c = config(R"({"a1": [0.5, 1]})");
  const DesignSpace a(c, exploration::default_scenario());
  Scenario other = exploration::default_scenario();
  other.max_steps = 99;
  const DesignSpace b(c, other);
  EXPECT_EQ(a.point_key(Genome{0}), a.point_key(Genome{0}));
  EXPECT_NE(a.point_key(Genome{0}), a.point_key(Genome{1}));
  EXPECT_NE(a.point_key(Genome{0}), b.point_key(Genome{0}));
  EXPECT_EQ(a.point_key(Genome{0}).size(), 16u);
}

RC_GTEST_PROP(DesignSpace, SeededPlacementIsValidExactAndRepeatable, (uint64_t seed)) {
  const int map = *rc::gen::inRange(2, 40);
  const int cells = map * map;
  const int robots = *rc::gen::inRange(1, std::max(2, cells / 2));
  const double density = *rc::gen::element(0.0, 0.1, 0.3, 0.45);
  const DseConfig c = config(R"({"mapSize": [)" + std::to_string(map) + R"(], "nRobots": [)" + std::to_string(robots) +
                             R"(], "obstacleDensity": [)" + std::to_string(density) + R"(], "seed": [)" +
                             std::to_string(seed % 1000000) + R"(]})");
  const DesignSpace space(c, exploration::default_scenario());
  const Genome g{0, 0, 0, 0};
  const auto obstacles = static_cast<std::size_t>(std::llround(density * cells));
  RC_PRE(obstacles + static_cast<std::size_t>(robots) <= static_cast<std::size_t>(cells));
  const Scenario s = space.scenario(g, 0);   // validates: distinct, in the map, robots not on obstacles
  RC_ASSERT(s.robots.size() == static_cast<std::size_t>(robots));
  RC_ASSERT(s.obstacles.size() == obstacles);
  for (const auto& r : s.robots) RC_ASSERT(r[0] - std::floor(r[0]) == 0.5);   // cell centres
  RC_ASSERT(exploration::free_cell_count(s) == cells - static_cast<int64_t>(obstacles));
  RC_ASSERT(json_io::to_json(space.scenario(g, 0)) == json_io::to_json(s));
}
