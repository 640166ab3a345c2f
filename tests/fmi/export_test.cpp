// The exported FMUs' model descriptions against the FMI 2.0 rules (tests/fmi/fmi2_rules.hpp),
// their archives' layout, and the variable list derived from the port records.
#include <gtest/gtest.h>
#include <zip.h>

#include <set>

#include "fmi/export/fmu_export.hpp"
#include "fmi/fmu/model_description.hpp"
#include "spec/exploration/scenario.hpp"
#include "tests/fmi/fmi2_rules.hpp"
#include "tests/fmi/scratch.hpp"

namespace {

using namespace swarmcheck;
using swarmcheck::testing::fmi2_problems;

std::vector<std::string> entries(const std::string& archive_bytes) {
  zip_error_t e;
  zip_error_init(&e);
  zip_source_t* src = zip_source_buffer_create(archive_bytes.data(), archive_bytes.size(), 0, &e);
  zip_t* za = zip_open_from_source(src, ZIP_RDONLY, &e);
  std::vector<std::string> names;
  if (!za) return names;
  for (zip_int64_t k = 0; k < zip_get_num_entries(za, 0); ++k) names.emplace_back(zip_get_name(za, static_cast<zip_uint64_t>(k), 0));
  zip_close(za);
  return names;
}

std::string join(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

}  // namespace

TEST(FmiExport, EveryModelDescriptionFollowsTheFmi2RulesForOneFourAndThirteenRobots) {
  for (const int32_t n : {1, 4, 13}) {
    const exploration::Scenario s = fmi::scenario_with_robots(exploration::default_scenario(), n);
    for (const fmi::Kind kind : {fmi::Kind::environment, fmi::Kind::controller, fmi::Kind::body}) {
      const std::string xml = fmi::model_description_xml(fmi::fmu_setup(kind, s), "test");
      const auto problems = fmi2_problems(xml);
      EXPECT_TRUE(problems.empty()) << fmi::to_string(kind) << " with " << n << " robots:\n" << join(problems);
    }
  }
  // The real system's FMUs: the thesis interface's Controller and Body, and the thesis preset's.
  exploration::Scenario preset = exploration::default_scenario();
  preset.controller = exploration::ControllerKind::thesis;
  preset.body.kind = exploration::BodyKind::intocps;
  for (const fmi::Kind kind : {fmi::Kind::controller, fmi::Kind::body})
    for (const fmi::FmuSetup& setup : {fmi::fmu_setup(kind, fmi::thesis_interface_scenario(), fmi::Interface::thesis),
                                       fmi::fmu_setup(kind, preset)}) {
      const auto problems = fmi2_problems(fmi::model_description_xml(setup, "test"));
      EXPECT_TRUE(problems.empty()) << fmi::model_name(setup) << ":\n" << join(problems);
    }
}

TEST(FmiExport, TheRuleCheckerCatchesBrokenDescriptions) {
  const std::string good = fmi::model_description_xml(fmi::fmu_setup(fmi::Kind::controller, exploration::default_scenario()), "t");
  ASSERT_TRUE(fmi2_problems(good).empty());
  const auto broken = [&](const std::string& from, const std::string& to) {
    std::string x = good;
    const std::size_t at = x.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    x.replace(at, from.size(), to);
    return !fmi2_problems(x).empty();
  };
  EXPECT_TRUE(broken("causality=\"input\" variability=\"continuous\"", "causality=\"input\" variability=\"fixed\""));
  EXPECT_TRUE(broken("<Real start=\"0\"/>", "<Real/>"));                              // an input without start
  EXPECT_TRUE(broken("valueReference=\"1\"", "valueReference=\"0\""));                // a reference used twice
  EXPECT_TRUE(broken("<Unknown index=\"11\" dependencies=\"\"/>", ""));               // an output not listed
  EXPECT_TRUE(broken("initial=\"exact\"", "initial=\"calculated\""));                // a parameter calculated
  EXPECT_TRUE(broken("fmiVersion=\"2.0\"", "fmiVersion=\"3.0\""));
  EXPECT_TRUE(broken("name=\"k_v\"", "name=\"k_beta\""));                            // a name used twice
}

TEST(FmiExport, VariablesCarryTheThesisNamesGeneralisedToNRobotsWithStableValueReferences) {
  const exploration::Scenario s = fmi::scenario_with_robots(exploration::default_scenario(), 6);
  const auto env = fmi::make_component(fmi::fmu_setup(fmi::Kind::environment, s));
  const auto& t = env->table();
  for (const char* name : {"mapSize", "step_size", "s_range", "a1", "a2", "ertu_perc", "eta", "max_ph", "phi", "lambda",
                           "x_1", "y_6", "onDestination1Input", "onDestination6Input", "xDesired1", "yDesired6",
                           "onDestinationOutput", "eP", "sTime", "lx_3", "ox_4", "oy_1", "nRobots"})
    EXPECT_NE(t.find(std::string(name)), nullptr) << name;
  EXPECT_EQ(t.find(std::string("x_7")), nullptr);
  // Scalars first (their references do not depend on N), then each robot's groups in turn.
  const auto four = fmi::make_component(fmi::fmu_setup(fmi::Kind::environment, exploration::default_scenario()));
  EXPECT_EQ(t.find(std::string("mapSize"))->value_reference, four->table().find(std::string("mapSize"))->value_reference);
  EXPECT_EQ(t.find(std::string("eP"))->value_reference, four->table().find(std::string("eP"))->value_reference);
  const uint32_t robot1 = t.find(std::string("lx_1"))->value_reference;
  const uint32_t per_robot = t.find(std::string("lx_2"))->value_reference - robot1;
  EXPECT_EQ(t.find(std::string("xDesired5"))->value_reference, t.find(std::string("xDesired1"))->value_reference + 4 * per_robot);
  std::set<uint32_t> refs;
  for (const auto& v : t.variables()) EXPECT_TRUE(refs.insert(v.value_reference).second) << v.name;
  const auto ctrl = fmi::make_component(fmi::fmu_setup(fmi::Kind::controller, s));
  for (const char* name : {"x", "y", "phi", "xDesired", "yDesired", "onDestinationInput", "servoLeft", "servoRight",
                           "onDestinationOutput", "beta", "rho", "v", "w", "maneuver", "k_beta", "k_v"})
    EXPECT_NE(ctrl->table().find(std::string(name)), nullptr) << name;
}

TEST(FmiExport, AnArchiveHoldsTheDescriptionTheLibraryAndTheSetupAndIsTheSameBytesTwice) {
  const auto setup = fmi::fmu_setup(fmi::Kind::environment, exploration::default_scenario());
  const std::string a = fmi::fmu_archive(setup);
  EXPECT_EQ(a, fmi::fmu_archive(setup));
  const auto names = entries(a);
  EXPECT_EQ(names, (std::vector<std::string>{"modelDescription.xml", "binaries/linux64/swarmcheck_environment.so",
                                             "resources/swarmcheck-fmu.json"}));
  const auto body = fmi::fmu_setup(fmi::Kind::body, exploration::default_scenario());
  EXPECT_EQ(entries(fmi::fmu_archive(body))[1], "binaries/linux64/swarmcheck_body.so");
  EXPECT_NE(fmi::fmu_guid(setup), fmi::fmu_guid(body));
}

TEST(FmiExport, RobotsSpreadOverFreeCellsAndTooManyAreRefused) {
  const exploration::Scenario d = exploration::default_scenario();
  const exploration::Scenario s = fmi::scenario_with_robots(d, 20);
  EXPECT_EQ(s.robots.size(), 20u);
  EXPECT_NO_THROW(exploration::validate(s));
  EXPECT_EQ(fmi::scenario_with_robots(d, 4).robots, d.robots);
  EXPECT_THROW(fmi::scenario_with_robots(d, 97), InputError);   // 96 free cells
  EXPECT_THROW(fmi::scenario_with_robots(d, 0), InputError);
}
