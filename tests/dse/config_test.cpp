// DSE configurations: the thesis's own file, the names table, and every bad input with its path.
#include <gtest/gtest.h>

#include "impl/dse/config.hpp"
#include "impl/dse/names.hpp"
#include "spec/util/input_error.hpp"

using namespace swarmcheck;
using namespace swarmcheck::dse;

namespace {

std::string error_of(const std::string& text) {
  try {
    parse_dse_config(text, "c.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

// A valid configuration with one part replaced.
std::string with(const std::string& key, const std::string& value) {
  std::map<std::string, std::string> parts{
      {"algorithm", R"({"type": "exhaustive"})"},
      {"parameters", R"({"a1": [0.5, 1], "rule": ["thesis", "stochastic"]})"},
      {"parameterConstraints", R"([])"},
      {"objectiveDefinitions", R"({"externalScripts": {}, "internalFunctions": {"e": {"columnID": "eP", "objectiveType": "max"}}})"},
      {"objectiveConstraints", R"([])"},
      {"ranking", R"({"pareto": {"e": "+"}})"}};
  parts[key] = value;
  std::string out = "{";
  for (const auto& [k, v] : parts) out += (out.size() > 1 ? ", \"" : "\"") + k + "\": " + v;
  return out + "}";
}

}  // namespace

TEST(DseConfig, TheThesisConfigurationReads) {
  const DseConfig c = load_dse_config(std::string(SWARMCHECK_SOURCE_DIR) + "/scenarios/thesis/dse/ertu.dse.json");
  ASSERT_EQ(c.parameters.size(), 1u);
  EXPECT_EQ(c.parameters[0].knob, Knob::ertu);
  EXPECT_EQ(c.parameters[0].values.size(), 8u);
  EXPECT_EQ(c.parameters[0].values[7].number, 0.009);
  ASSERT_EQ(c.objectives.size(), 2u);
  EXPECT_EQ(c.objectives[0].name, "explorationPercentage");
  EXPECT_EQ(c.objectives[0].column.series, Series::eP);
  EXPECT_EQ(c.objectives[1].column.series, Series::sTime);
  ASSERT_EQ(c.pareto.size(), 2u);
  EXPECT_TRUE(c.pareto[0].maximise);
  EXPECT_FALSE(c.pareto[1].maximise);
  EXPECT_EQ(c.design_space_size(), 8u);
}

TEST(DseNames, IntoCpsAndPlainNamesReachTheSameKnob) {
  EXPECT_EQ(knob_of("{Environment}.EnvironmentInstance.ertu_perc"), Knob::ertu);
  EXPECT_EQ(knob_of("{Environment}.env.ertu_perc"), Knob::ertu);
  EXPECT_EQ(knob_of("ertu"), Knob::ertu);
  EXPECT_EQ(knob_of("mapSize"), knob_of("map_size"));
  EXPECT_EQ(knob_of("nRobots"), Knob::robot_count);
  EXPECT_FALSE(knob_of("{Controller}.c.ertu_perc").has_value());   // another FMU's variable
  EXPECT_FALSE(knob_of("k_v").has_value());
  EXPECT_EQ(column_of("{Environment}.EnvironmentInstance.sTime")->series, Series::sTime);
  EXPECT_EQ(column_of("distance_3")->robot, 2);
  EXPECT_FALSE(column_of("distance_0").has_value());
  EXPECT_FALSE(column_of("distance_x").has_value());
}

TEST(DseConfig, GeneticOptionsReadInIntoCpsUnits) {
  const DseConfig c = parse_dse_config(with("algorithm", R"({"type": "genetic", "initialPopulation": 6,
      "initialPopulationDistribution": "uniform", "mutationProbability": 25, "parentSelectionStrategy": "random",
      "maxGenerationsWithoutImprovement": 3, "seed": 9})"), "c.json");
  EXPECT_EQ(c.algorithm, Algorithm::genetic);
  EXPECT_EQ(c.genetic.initial_population, 6);
  EXPECT_EQ(c.genetic.distribution, InitialDistribution::uniform);
  EXPECT_EQ(c.genetic.mutation_probability, 0.25);
  EXPECT_EQ(c.genetic.selection, ParentSelection::random);
  EXPECT_EQ(c.genetic.max_generations_without_improvement, 3);
  EXPECT_EQ(c.genetic.seed, 9u);
}

TEST(DseConfig, EveryBadInputNamesItsJsonPathAndWhatWasExpected) {
  EXPECT_NE(error_of("{\"parameters\": [}").find("c.json:1:17: not valid JSON"), std::string::npos);
  EXPECT_EQ(error_of(R"({"colour": 1})"),
            "c.json: colour: unknown key (expected one of: algorithm, objectiveConstraints, objectiveDefinitions, "
            "parameterConstraints, parameters, ranking, scenarios)");
  const std::pair<std::string, std::string> cases[] = {
      {with("parameters", R"({"k_v": [1]})"), "c.json: parameters[\"k_v\"]: unknown parameter (known: s_range"},
      {with("parameters", R"({"a1": []})"), "c.json: parameters[\"a1\"]: expected a non-empty list of values"},
      {with("parameters", R"({"rule": [1]})"), "c.json: parameters[\"rule\"][0]: expected a string"},
      {with("parameters", R"({"rule": ["fast"]})"), "c.json: parameters[\"rule\"][0]: expected one of thesis|deterministic|stochastic"},
      {with("parameters", R"({"controller": ["pid"]})"), "c.json: parameters[\"controller\"][0]: expected one of swarmcheck|thesis"},
      {with("parameters", R"({"body": ["rigid"]})"), "c.json: parameters[\"body\"][0]: expected one of kinematic|intocps"},
      {with("parameters", R"({"a1": [1, 1]})"), "c.json: parameters[\"a1\"][1]: repeats the value at [0]"},
      {with("parameters", R"({"s_range": [1.5]})"), "c.json: parameters[\"s_range\"][0]: expected an integer in [1, 1048576], got 1.5"},
      {with("parameters", R"({"ertu": [1], "ertu_perc": [2]})"), "c.json: parameters[\"ertu_perc\"]: sets the same thing as parameters[\"ertu\"]"},
      {with("parameters", R"({"replicates": [0]})"), "c.json: parameters[\"replicates\"][0]: expected an integer in [1, 1000]"},
      {with("parameters", R"({"obstacleDensity": [1]})"), "expected a share in [0, 1), got 1"},
      {with("parameterConstraints", R"~(["a1 < )"])~"), "c.json: parameterConstraints[0], column 6: expected a number, a name or '('"},
      {with("parameterConstraints", R"([3])"), "c.json: parameterConstraints[0]: expected an expression (a string), got an integer"},
      {with("objectiveConstraints", R"(["speed > 1"])"), "c.json: objectiveConstraints[0], column 1: unknown name 'speed' (known: e, s_range"},
      {with("objectiveDefinitions", R"({"externalScripts": {"x": {}}, "internalFunctions": {}})"), "c.json: objectiveDefinitions.externalScripts: external scripts are not supported"},
      {with("objectiveDefinitions", R"({"internalFunctions": {}})"), "c.json: objectiveDefinitions.internalFunctions: expected an object with at least one objective"},
      {with("objectiveDefinitions", R"({"internalFunctions": {"e": {"columnID": "speed", "objectiveType": "max"}}})"), "c.json: objectiveDefinitions.internalFunctions[\"e\"].columnID: unknown column \"speed\""},
      {with("objectiveDefinitions", R"({"internalFunctions": {"e": {"columnID": "eP", "objectiveType": "median"}}})"), "objectiveType: expected \"max\", \"min\" or \"mean\", got \"median\""},
      {with("objectiveDefinitions", R"({"internalFunctions": {"a1": {"columnID": "eP", "objectiveType": "max"}}})"), "an objective may not have a parameter's name"},
      {with("ranking", R"({"pareto": {"time": "-"}})"), "c.json: ranking.pareto[\"time\"]: not an objective"},
      {with("ranking", R"({"pareto": {"e": "up"}})"), "expected \"+\" (maximise) or \"-\" (minimise), got \"up\""},
      {with("algorithm", R"({"type": "annealing"})"), "c.json: algorithm.type: expected \"exhaustive\" or \"genetic\""},
      {with("algorithm", R"({"type": "genetic", "initialPopulation": 1})"), "c.json: algorithm.initialPopulation: expected an integer in [2, 10000], got 1"},
      {with("algorithm", R"({"type": "genetic", "mutationProbability": 150})"), "c.json: algorithm.mutationProbability: expected a percentage in [0, 100], got 150"},
      {with("algorithm", R"({"type": "genetic", "parentSelectionStrategy": "best"})"), "c.json: algorithm.parentSelectionStrategy"},
      {with("algorithm", R"({"type": "exhaustive", "initialPopulation": 4})"), "c.json: algorithm.initialPopulation: unknown key"},
      {with("scenarios", R"(["s1"])"), "c.json: scenarios: expected []"},
  };
  for (const auto& [text, want] : cases) EXPECT_NE(error_of(text).find(want), std::string::npos) << error_of(text) << "\nwanted: " << want;
}
