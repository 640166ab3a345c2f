// `fmu export --interface thesis`: the Environment FMU has the variables of thesis A's own
// Environment FMU (name, causality, type: its handshake Real), and run with the parameters of
// the thesis's published multi-model it is swarmcheck's Environment under those parameters, step
// for step, bit for bit.
#include <gtest/gtest.h>

#include <bit>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "fmi/export/fmu_export.hpp"
#include "fmi/fmu/model_description.hpp"
#include "fmi/master/master.hpp"
#include "fmi/master/outputs_csv.hpp"
#include "impl/exploration/environment.hpp"
#include "spec/exploration/scenario.hpp"
#include "swarmcheck/exploration.hpp"
#include "tests/fmi/scratch.hpp"

namespace {

using namespace swarmcheck;
namespace fm = swarmcheck::fmi::master;
using Json = nlohmann::ordered_json;

// The thesis's Environment FMU's variables (its modelDescription.xml), name: causality, type.
std::vector<std::tuple<std::string, std::string, fm::VarType>> thesis_environment_variables() {
  using fm::VarType;
  std::vector<std::tuple<std::string, std::string, VarType>> v{
      {"a1", "parameter", VarType::real},        {"a2", "parameter", VarType::real},
      {"ertu_perc", "parameter", VarType::real}, {"eta", "parameter", VarType::real},
      {"flag", "parameter", VarType::integer},   {"lambda", "parameter", VarType::real},
      {"mapSize", "parameter", VarType::integer}, {"max_ph", "parameter", VarType::real},
      {"nRobots", "parameter", VarType::integer}, {"onDestinationOutput", "output", VarType::real},
      {"phi", "parameter", VarType::real},       {"port", "parameter", VarType::integer},
      {"s_range", "parameter", VarType::integer}, {"step_size", "parameter", VarType::real},
      {"stepCount", "parameter", VarType::integer}, {"nObstacles", "parameter", VarType::integer},
      {"eP", "output", VarType::real},           {"sTime", "output", VarType::real}};
  for (int k = 1; k <= 4; ++k) {
    const std::string i = std::to_string(k);
    for (const auto& [name, causality] : std::vector<std::pair<std::string, std::string>>{
             {"onDestination" + i + "Input", "input"}, {"x_" + i, "input"}, {"y_" + i, "input"},
             {"xDesired" + i, "output"}, {"yDesired" + i, "output"}, {"lx_" + i, "parameter"}, {"ly_" + i, "parameter"}})
      v.emplace_back(name, causality, VarType::real);
  }
  for (int k = 1; k <= 10; ++k) {
    v.emplace_back("ox_" + std::to_string(k), "parameter", VarType::integer);
    v.emplace_back("oy_" + std::to_string(k), "parameter", VarType::integer);
  }
  return v;
}

}  // namespace

TEST(FmiThesisInterface, TheEnvironmentHasEveryVariableOfTheThesissEnvironmentWithItsCausalityAndType) {
  const auto setup = fmi::fmu_setup(fmi::Kind::environment, fmi::thesis_interface_scenario(), fmi::Interface::thesis);
  const fm::ModelDescription md = fm::read_model_description(fmi::model_description_xml(setup, "t"), "thesis.xml");
  const auto expected = thesis_environment_variables();
  for (const auto& [name, causality, type] : expected) {
    const fm::ModelVariable* v = md.find(name);
    ASSERT_NE(v, nullptr) << name;
    EXPECT_EQ(v->causality, causality) << name;
    EXPECT_EQ(v->type, type) << name;
  }
  // Besides them only the four the thesis's code fixes and swarmcheck's rules read.
  EXPECT_EQ(md.variables.size(), expected.size() + 4);
  for (const char* extra : {"cellSize", "epsilon", "rule", "seed"}) EXPECT_NE(md.find(extra), nullptr) << extra;
  EXPECT_EQ(md.model_name, "swarmcheck Environment (thesis interface)");
  EXPECT_EQ(md.find("nRobots")->start_number, 4);
  EXPECT_EQ(md.find("ertu_perc")->start_number, 0.002);
  EXPECT_EQ(md.find("rule")->start_number, 0);   // thesis
}

TEST(FmiThesisInterface, ThePublishedMultiModelsEnvironmentParametersRunSwarmchecksEnvironmentBitForBit) {
  const std::filesystem::path dir = swarmcheck::testing::fmi_scratch("thesis-interface");
  fmi::write_fmu(fmi::fmu_setup(fmi::Kind::environment, fmi::thesis_interface_scenario(), fmi::Interface::thesis),
                 (dir / "Environment.fmu").string());
  // The Environment's parameters in the thesis's mm-new/mm.json; its onDestination inputs
  // unconnected keep their start value 1.0 (every robot idle), so it plans whenever its flag says.
  const std::string env = "{Environment}.EnvironmentInstance.";
  Json mm;
  mm["fmus"] = {{"{Environment}", "Environment.fmu"}};
  mm["parameters"] = {{env + "lx_1", 0.5}, {env + "ly_1", 0.5}, {env + "lx_2", 9.5}, {env + "ly_2", 9.5},
                      {env + "mapSize", 12},  {env + "nRobots", 2},  {env + "nObstacles", 3}, {env + "ox_1", 4},
                      {env + "ox_2", 4},      {env + "ox_3", 5},     {env + "oy_1", 4},       {env + "oy_2", 5},
                      {env + "oy_3", 5}};
  std::ofstream(dir / "mm.json") << mm.dump();
  fm::CoSimConfig config;
  config.end_s = 300;
  fm::Master master(fm::read_multimodel((dir / "mm.json").string()), config, fm::Algorithm::jacobi);
  exploration::Scenario s = fmi::thesis_interface_scenario();
  s.map_size = 12;
  s.robots = {{0.5, 0.5}, {9.5, 9.5}};
  s.obstacles = {{4, 4}, {4, 5}, {5, 5}};
  impl::exploration::Environment library(s, ExplorationOptions{});
  const auto bits = [](double v) { return std::bit_cast<uint64_t>(v); };
  const auto out = [&](const std::string& name) { return master.value(master.port(env + name)); };
  while (!master.done()) {
    master.step();
    library.step(true);
    const auto& e = library.state();
    ASSERT_EQ(bits(out("eP")), bits(e.progress.eP)) << "step " << master.steps();
    ASSERT_EQ(out("onDestinationOutput"), e.handshake.on_destination_output == 1 ? 1.0 : 0.0) << "step " << master.steps();
    for (std::size_t r = 0; r < 2; ++r) {
      ASSERT_EQ(bits(out("xDesired" + std::to_string(r + 1))), bits(e.robots[r].waypoint[0])) << "step " << master.steps();
      ASSERT_EQ(bits(out("yDesired" + std::to_string(r + 1))), bits(e.robots[r].waypoint[1])) << "step " << master.steps();
    }
    // Robots 3 and 4 do not take part: their outputs stay at their start positions.
    ASSERT_EQ(out("xDesired3"), 9.5);
    ASSERT_EQ(out("yDesired4"), 9.5);
  }
  EXPECT_GT(library.state().planning_steps, 100);
  EXPECT_GT(out("eP"), 10.0);
  std::filesystem::remove_all(dir);
}

// Acceptance of issue 35: thesis A's INTO-CPS project laid out as published (FMUs/, its FMU keys
// and instance names, Multi-models/mm-new/mm.json's connections and parameters, the configuration's
// keys), with `fmu export --intocps DIR --interface thesis`'s FMUs in place of the thesis's, runs
// in the master; its outputs.csv has the engine's 35 columns in the engine's order; and the run is
// `swarmcheck run --mode cosim` with the thesis preset (rule, controller and body the thesis's),
// value for value at every step, to the completion step.
TEST(FmiThesisInterface, ThePublishedProjectWithSwarmchecksFmusIsRunModeCosimUnderTheThesisPresetValueForValue) {
  const std::filesystem::path dir = swarmcheck::testing::fmi_scratch("thesis-project");
  const exploration::Scenario scenario = fmi::thesis_interface_scenario();
  const fmi::ThesisProject project = fmi::write_intocps_thesis(scenario, dir.string());
  EXPECT_EQ(project.multimodel, (dir / "Multi-models" / "mm-new" / "mm.json").string());
  for (const char* fmu : {"Environment.fmu", "UController.fmu", "Body_Block1.fmu", "Body_Block4.fmu"})
    EXPECT_TRUE(std::filesystem::exists(dir / "FMUs" / fmu)) << fmu;
  fm::Master master(fm::read_multimodel(project.multimodel), fm::read_config(project.config), fm::Algorithm::jacobi);

  // The engine's columns: time, step-size, then the connected outputs by name.
  std::ostringstream header;
  fm::OutputsCsv(master).header(header);
  std::vector<std::string> columns;
  std::stringstream cells(header.str().substr(0, header.str().find('\n')));
  for (std::string c; std::getline(cells, c, ',');) columns.push_back(c);
  ASSERT_EQ(columns.size(), 35u);
  EXPECT_EQ(columns[0], "time");
  EXPECT_EQ(columns[1], "step-size");
  EXPECT_TRUE(std::is_sorted(columns.begin() + 2, columns.end()));
  EXPECT_EQ(columns[2], "{Controller}.ControllerInstance1.onDestinationOutput");
  EXPECT_EQ(columns[34], "{Robot4}.Robot4Instance.robot_y");

  exploration::Scenario s = scenario;
  s.mode = exploration::Mode::cosim;
  s.controller = exploration::ControllerKind::thesis;
  s.body.kind = exploration::BodyKind::intocps;
  Exploration library(s);
  const auto bits = [](double v) { return std::bit_cast<uint64_t>(v); };
  const std::string env = "{Environment}.EnvironmentInstance.";
  const fm::Master::Port eP = master.port(env + "eP");
  int64_t fmu_completion = -1;
  while (!master.done()) {
    master.step();
    library.step();
    ASSERT_EQ(bits(master.value(eP)), bits(library.eP())) << "step " << master.steps();
    for (std::size_t r = 0; r < s.robots.size(); ++r) {
      const std::string k = std::to_string(r + 1);
      const std::string robot = "{Robot" + k + "}.Robot" + k + "Instance.";
      const auto& body = library.bodies()[r];
      const auto& wp = library.robots()[r].waypoint;
      const auto at = [&](const std::string& port) { return bits(master.value(master.port(port))); };
      ASSERT_EQ(at(robot + "robot_x"), bits(body.x_m)) << "step " << master.steps() << " robot " << k;
      ASSERT_EQ(at(robot + "robot_y"), bits(body.y_m)) << "step " << master.steps() << " robot " << k;
      ASSERT_EQ(at(robot + "robot_theta"), bits(body.theta_rad)) << "step " << master.steps() << " robot " << k;
      ASSERT_EQ(at(env + "xDesired" + k), bits(wp[0])) << "step " << master.steps() << " robot " << k;
      ASSERT_EQ(at(env + "yDesired" + k), bits(wp[1])) << "step " << master.steps() << " robot " << k;
    }
    if (fmu_completion < 0 && master.value(eP) >= 100) fmu_completion = master.steps();
  }
  ASSERT_TRUE(library.completion_step().has_value());
  EXPECT_EQ(fmu_completion, *library.completion_step());
  EXPECT_EQ(master.steps(), *library.completion_step());
  std::filesystem::remove_all(dir);
}
