// Scenario files: defaults, JSON derived from the Hana declaration, and every bad input.
#include <gtest/gtest.h>

#include "spec/exploration/scenario.hpp"
#include "spec/util/hana_json.hpp"

using namespace swarmcheck;
using namespace swarmcheck::exploration;

namespace {
std::string error_of(const std::string& text) {
  try {
    parse_scenario(text, "s.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}
const std::string kMinimal = R"({"map_size": 4, "robots": [[0.5, 0.5]]})";
}  // namespace

TEST(Scenario, DefaultIsTheThesisSetUpAndValid) {
  const Scenario s = default_scenario();
  EXPECT_NO_THROW(validate(s));
  EXPECT_EQ(s.map_size, 10);
  EXPECT_EQ(s.robots.size(), 4u);
  EXPECT_EQ(s.obstacles, (std::vector<CellIndex>{{4, 4}, {4, 5}, {5, 4}, {5, 5}}));
  EXPECT_EQ(free_cell_count(s), 96);
}

TEST(Scenario, MissingKeysTakeTheBuiltInDefaults) {
  const Scenario s = parse_scenario(kMinimal, "s.json");
  EXPECT_EQ(s.map_size, 4);
  EXPECT_EQ(s.cell_size, 1.0);
  EXPECT_EQ(s.params.a1, 0.5);
  EXPECT_EQ(s.rule, RuleSet::deterministic);
  EXPECT_TRUE(s.obstacles.empty());   // no obstacles unless listed
}

TEST(Scenario, WrittenScenarioReadsBackEqual) {
  const Scenario s = default_scenario();
  const Scenario t = parse_scenario(json_io::to_json(s).dump(), "s.json");
  EXPECT_EQ(json_io::to_json(t), json_io::to_json(s));
  EXPECT_EQ(json_io::field_names<Params>().front(), "s_range");
}

TEST(Scenario, EveryBadInputNamesItsPathAndWhatWasExpected) {
  EXPECT_EQ(error_of("{\"map_size\": 4,\n \"robots\": [1,]}"),
            "s.json:2:15: not valid JSON: syntax error while parsing value - unexpected ']'; "
            "expected '[', '{', or a literal");
  EXPECT_EQ(error_of("[1]"), "s.json: (top level): expected an object");
  EXPECT_EQ(error_of(R"({"map_size": 4, "robots": [[0.5, 0.5]], "colour": 1})"),
            "s.json: colour: unknown key (expected one of: map_size, cell_size, robots, "
            "obstacles, params, rule, mode, seed, max_steps, controller, body)");
  EXPECT_EQ(error_of(R"({"map_size": "4", "robots": []})"),
            "s.json: map_size: expected an integer, got a string");
  EXPECT_EQ(error_of(R"({"map_size": 0, "robots": [[0.5, 0.5]]})"),
            "s.json: map_size: expected an integer in [1, 65536], got 0");
  EXPECT_EQ(error_of(R"({"robots": [[0.5, 0.5]]})"),
            "s.json: map_size: missing (the map's side in cells)");
  EXPECT_EQ(error_of(R"({"map_size": 4, "robots": [[4.5, 0.5]], "obstacles": []})"),
            "s.json: robots[0]: expected a position [x, y] in metres with 0 <= x, y < 4, got [4.5, 0.5]");
  EXPECT_EQ(error_of(R"({"map_size": 4, "robots": [[1.5, 1.5]], "obstacles": [[1, 1]]})"),
            "s.json: robots[0]: starts in cell [1, 1], which is obstacles[0]");
  EXPECT_EQ(error_of(R"({"map_size": 4, "robots": [[1.5, 1.5], [1.2, 1.9]], "obstacles": []})"),
            "s.json: robots[1]: starts in cell [1, 1], already taken by robots[0]");
  EXPECT_EQ(error_of(R"({"map_size": 4, "robots": [[0.5, 0.5]], "obstacles": [[4, 0]]})"),
            "s.json: obstacles[0]: expected a cell [i, j] with 0 <= i, j < 4, got [4, 0]");
  EXPECT_EQ(error_of(R"({"map_size": 4, "robots": [[0.5]], "obstacles": []})"),
            "s.json: robots[0]: expected a list of 2 values, got 1 values");
  EXPECT_EQ(error_of(R"({"map_size": 4, "robots": [[0.5, 0.5]], "params": {"a1": -1}})"),
            "s.json: params.a1: expected a finite number > 0, got -1");
  EXPECT_EQ(error_of(R"({"map_size": 4, "robots": [[0.5, 0.5]], "params": {"s_range": 0}})"),
            "s.json: params.s_range: expected an integer in [1, 1048576], got 0");
  EXPECT_EQ(error_of(R"({"map_size": 4, "robots": [[0.5, 0.5]], "rule": "greedy"})"),
            "s.json: rule: expected one of thesis|deterministic|stochastic, got \"greedy\"");
  EXPECT_EQ(error_of(R"({"map_size": 4, "robots": [[0.5, 0.5]], "params": {"step_size": 0.6}})"),
            "s.json: params.step_size: expected at most 0.5 s in cosim mode (the "
            "controllers are checked to arrive on both bodies up to this step), got 0.6");
  EXPECT_EQ(error_of(R"({"map_size": 4, "robots": [[0.5, 0.5]], "controller": "pid"})"),
            "s.json: controller: expected one of swarmcheck|thesis, got \"pid\"");
  EXPECT_EQ(error_of(R"({"map_size": 4, "robots": [[0.5, 0.5]], "body": {"kind": "intocps", "parameters": {"mu": -1}}})"),
            "s.json: body.parameters.mu: expected a number >= 0, got -1");
  EXPECT_EQ(error_of(R"({"map_size": 4, "robots": [[0.5, 0.5]], "body": {"kind": "intocps", "parameters": {"initial_position[1]": 2}}})"),
            "s.json: body.parameters.initial_position[1]: a robot's position is its entry in robots; only "
            "initial_position[2] (the heading) is a body parameter");
  EXPECT_EQ(error_of(R"({"map_size": 4, "robots": [[0.5, 0.5]], "seed": -1})"),
            "s.json: seed: expected a non-negative integer, got -1");
  EXPECT_EQ(error_of(R"({"map_size": 4, "robots": [[0.5, 0.5]], "max_steps": 2147483648})"),
            "s.json: max_steps: expected an integer in [0, 2^31 - 1], got 2147483648");
  EXPECT_EQ(error_of(R"({"map_size": 4, "robots": [], "obstacles": []})"),
            "s.json: robots: expected at least one robot");
}

TEST(Scenario, BundledDefaultFileEqualsTheBuiltInDefault) {
  const Scenario s = load_scenario(std::string(SWARMCHECK_SOURCE_DIR) + "/scenarios/default.json");
  EXPECT_EQ(json_io::to_json(s), json_io::to_json(default_scenario()));
}
