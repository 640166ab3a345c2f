// The FMU co-simulation against the library: the thesis multi-model of a scenario, run by the
// master with Jacobi steps, gives `run --mode cosim`'s robot poses, waypoints, eP and completion
// step, bit for bit, step by step. And the handshake under Gauss-Seidel: the flag handshake's
// stale acceptance (the failure `swarmcheck prove` refutes as handshake-gauss-seidel), which the
// epoch handshake does not have.
#include <gtest/gtest.h>

#include <bit>

#include "fmi/export/fmu_export.hpp"
#include "fmi/master/handshake_monitor.hpp"
#include "fmi/master/master.hpp"
#include "spec/exploration/scenario.hpp"
#include "swarmcheck/exploration.hpp"
#include "tests/fmi/scratch.hpp"

namespace {

using namespace swarmcheck;
namespace fm = swarmcheck::fmi::master;

exploration::Scenario small_stochastic() {
  exploration::Scenario s = exploration::default_scenario();
  s.map_size = 16;
  s.rule = exploration::RuleSet::stochastic;
  s.seed = 77;
  s.params.s_range = 2;
  s.obstacles = {{7, 7}, {7, 8}, {3, 12}, {12, 3}};
  return fmi::scenario_with_robots(s, 9);
}

exploration::Scenario thesis_rule() {
  exploration::Scenario s = exploration::default_scenario();
  s.rule = exploration::RuleSet::thesis;
  return s;
}

// Runs the FMU co-simulation and the library side by side, comparing every step.
void expect_the_same_run(const exploration::Scenario& scenario, const std::string& name) {
  const auto dir = swarmcheck::testing::fmi_scratch("cosim-" + name);
  fmi::write_intocps(scenario, fmi::Handshake::flag, dir.string());
  const fm::MultiModel mm = fm::read_multimodel((dir / "multimodel.json").string());
  const fm::CoSimConfig config = fm::read_config((dir / "coe.json").string());
  fm::Master master(mm, config, fm::Algorithm::jacobi);
  exploration::Scenario s = scenario;
  s.mode = exploration::Mode::cosim;
  Exploration library(s);
  const std::size_t n = s.robots.size();
  std::vector<std::array<fm::Master::Port, 5>> ports;   // x, y, theta, xDesired, yDesired per robot
  for (std::size_t r = 0; r < n; ++r) {
    const std::string i = std::to_string(r + 1);
    ports.push_back({master.port("{Body}.body" + i + ".robot_x"), master.port("{Body}.body" + i + ".robot_y"),
                     master.port("{Body}.body" + i + ".robot_theta"), master.port("{Environment}.environment.xDesired" + i),
                     master.port("{Environment}.environment.yDesired" + i)});
  }
  const fm::Master::Port eP = master.port("{Environment}.environment.eP");
  const auto bits = [](double v) { return std::bit_cast<uint64_t>(v); };
  int64_t fmu_completion = -1;
  while (!master.done()) {
    master.step();
    library.step();
    ASSERT_EQ(master.steps(), library.steps());
    ASSERT_EQ(bits(master.value(eP)), bits(library.eP())) << name << " step " << master.steps();
    for (std::size_t r = 0; r < n; ++r) {
      const auto& body = library.bodies()[r];
      const auto& wp = library.robots()[r].waypoint;
      ASSERT_EQ(bits(master.value(ports[r][0])), bits(body.x_m)) << name << " step " << master.steps() << " robot " << r;
      ASSERT_EQ(bits(master.value(ports[r][1])), bits(body.y_m)) << name << " step " << master.steps() << " robot " << r;
      ASSERT_EQ(bits(master.value(ports[r][2])), bits(body.theta_rad)) << name << " step " << master.steps();
      ASSERT_EQ(bits(master.value(ports[r][3])), bits(wp[0])) << name << " step " << master.steps() << " robot " << r;
      ASSERT_EQ(bits(master.value(ports[r][4])), bits(wp[1])) << name << " step " << master.steps() << " robot " << r;
    }
    if (fmu_completion < 0 && master.value(eP) >= 100) fmu_completion = master.steps();
  }
  ASSERT_TRUE(library.completion_step().has_value()) << name;
  EXPECT_EQ(fmu_completion, *library.completion_step()) << name;
  std::filesystem::remove_all(dir);
}

int64_t stale_acceptances(const std::filesystem::path& dir, fm::Algorithm algorithm, double& final_eP) {
  const fm::MultiModel mm = fm::read_multimodel((dir / "multimodel.json").string());
  const fm::CoSimConfig config = fm::read_config((dir / "coe.json").string());
  fm::Master master(mm, config, algorithm);
  fm::HandshakeMonitor monitor(master);
  EXPECT_TRUE(monitor.active());
  while (!master.done()) {
    master.step();
    monitor.after_step(master);
  }
  final_eP = master.value(master.port("{Environment}.environment.eP"));
  return monitor.stale_count();
}

}  // namespace

TEST(FmiCosim, JacobiFmuCosimulationOfTheDefaultScenarioIsTheLibraryRunBitForBit) {
  expect_the_same_run(exploration::default_scenario(), "default");
}

TEST(FmiCosim, JacobiFmuCosimulationOfNineStochasticRobotsIsTheLibraryRunBitForBit) {
  expect_the_same_run(small_stochastic(), "stochastic");
}

TEST(FmiCosim, JacobiFmuCosimulationUnderTheThesisRuleSetIsTheLibraryRunBitForBit) {
  expect_the_same_run(thesis_rule(), "thesis");
}

// The real system as the thesis ran it: the thesis's controller on the 20-sim body, in
// swarmcheck's interface (`fmu export --intocps DIR --preset thesis`).
TEST(FmiCosim, JacobiFmuCosimulationUnderTheThesisPresetIsTheLibraryRunBitForBit) {
  exploration::Scenario s = thesis_rule();
  s.controller = exploration::ControllerKind::thesis;
  s.body.kind = exploration::BodyKind::intocps;
  expect_the_same_run(s, "thesis-preset");
}

// The default controller on the 20-sim body (`--body intocps`).
TEST(FmiCosim, JacobiFmuCosimulationOfTheDefaultControllerOnTheIntocpsBodyIsTheLibraryRunBitForBit) {
  exploration::Scenario s = exploration::default_scenario();
  s.body.kind = exploration::BodyKind::intocps;
  expect_the_same_run(s, "intocps-body");
}

TEST(FmiCosim, GaussSeidelBreaksTheFlagHandshakeAndTheEpochHandshakeHoldsAndCompletes) {
  const auto flag = swarmcheck::testing::fmi_scratch("gs-flag");
  const auto epoch = swarmcheck::testing::fmi_scratch("gs-epoch");
  // Long enough for the Gauss-Seidel order to complete too (the exported end time is the Jacobi
  // library run's completion, 1023.7 s; Gauss-Seidel's epoch run takes longer).
  constexpr double kEnd_s = 3000.0;
  fmi::write_intocps(exploration::default_scenario(), fmi::Handshake::flag, flag.string(), kEnd_s);
  fmi::write_intocps(exploration::default_scenario(), fmi::Handshake::epoch, epoch.string(), kEnd_s);
  double eP = 0;
  EXPECT_EQ(stale_acceptances(flag, fm::Algorithm::jacobi, eP), 0);
  EXPECT_EQ(eP, 100.0);
  EXPECT_GT(stale_acceptances(flag, fm::Algorithm::gauss_seidel, eP), 0);
  EXPECT_LT(eP, 100.0);   // the controllers keep re-accepting: the Environment never sees them all idle
  EXPECT_EQ(stale_acceptances(epoch, fm::Algorithm::gauss_seidel, eP), 0);
  EXPECT_EQ(eP, 100.0);
  EXPECT_EQ(stale_acceptances(epoch, fm::Algorithm::jacobi, eP), 0);
  EXPECT_EQ(eP, 100.0);
  std::filesystem::remove_all(flag);
  std::filesystem::remove_all(epoch);
}
