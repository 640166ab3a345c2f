// The exported intocps Body FMU against thesis A's 20-sim Body_Block binary: loaded as a master
// loads it (unzipped, dlopen) and driven through its FMI 2.0 C API with the fixtures' protocol
// (fmi2SetupExperiment(0, 60), every parameter written, initialisation, then per row the inputs
// set and fmi2DoStep(k * 0.1, 0.1)), it gives the binary's outputs by bits at every row of the
// seven profiles. Both exports: `fmu export body --interface thesis` (Body_Block1.fmu) and
// `fmu export body --body intocps`. Unlike the binary (global state), two instances in one
// process each give their own profile's bits.
#include <gtest/gtest.h>

#include <bit>
#include <memory>
#include <string>
#include <vector>

#include "fmi/export/fmu_export.hpp"
#include "fmi/master/fmu_library.hpp"
#include "spec/exploration/scenario.hpp"
#include "tests/exploration/intocps_fixtures.hpp"
#include "tests/fmi/scratch.hpp"

namespace {

using namespace swarmcheck;
using fmi::master::FmuLibrary;
namespace fixtures = swarmcheck::testing;
using swarmcheck::testing::Fixture;
using swarmcheck::testing::kOutputs;

constexpr const char* kOutputNames[kOutputs] = {"robot_x", "robot_y", "robot_theta", "robot_z", "wheel_left_rotation",
                                                "wheel_right_rotation", "encoder_left_output", "encoder_right_output",
                                                "total_energy_used"};

void no_log(fmi2ComponentEnvironment, fmi2String, fmi2Status, fmi2String, fmi2String, ...) {}

// One instance driven with one fixture's protocol.
class Driven {
 public:
  Driven(const FmuLibrary& lib, const Fixture& f, const std::string& name) : lib_(lib), f_(f) {
    c_ = lib.api().instantiate(name.c_str(), fmi2CoSimulation, lib.description().guid.c_str(),
                               lib.resource_uri().c_str(), &callbacks_, fmi2False, fmi2False);
    EXPECT_NE(c_, nullptr);
    EXPECT_EQ(lib.api().setup_experiment(c_, fmi2False, 0, 0.0, fmi2True, 60.0), fmi2OK);
    for (const exploration::IntocpsBodyParameter& d : exploration::intocps_body_parameters()) {
      const double v = exploration::intocps_parameter_value(f.params, d);
      EXPECT_EQ(set(std::string(d.name), v), fmi2OK) << d.name;
    }
    EXPECT_EQ(lib.api().enter_initialization_mode(c_), fmi2OK);
    EXPECT_EQ(lib.api().exit_initialization_mode(c_), fmi2OK);
  }
  ~Driven() {
    if (c_) lib_.api().free_instance(c_);
  }
  Driven(const Driven&) = delete;
  Driven& operator=(const Driven&) = delete;

  // Row k's inputs and step (k >= 1), then the outputs; "" when they are the binary's bits.
  std::string row(std::size_t k) {
    if (k > 0) {
      if (set("servo_left_input", f_.rows[k][2]) != fmi2OK || set("servo_right_input", f_.rows[k][3]) != fmi2OK ||
          lib_.api().do_step(c_, static_cast<double>(k - 1) * 0.1, 0.1, fmi2True) != fmi2OK)
        return f_.name + " row " + std::to_string(k) + ": the FMU refused the step";
    }
    std::array<double, kOutputs> got{};
    for (int c = 0; c < kOutputs; ++c) {
      const fmi2ValueReference vr = lib_.description().find(kOutputNames[c])->value_reference;
      if (lib_.api().get_real(c_, &vr, 1, &got[static_cast<std::size_t>(c)]) != fmi2OK)
        return f_.name + ": fmi2GetReal failed";
    }
    return fixtures::compare(f_, k, got);
  }

 private:
  fmi2Status set(const std::string& name, double v) {
    const auto* var = lib_.description().find(name);
    if (var == nullptr) return fmi2Error;
    const fmi2ValueReference vr = var->value_reference;
    return lib_.api().set_real(c_, &vr, 1, &v);
  }
  const FmuLibrary& lib_;
  const Fixture& f_;
  fmi2CallbackFunctions callbacks_{no_log, nullptr, nullptr, nullptr, nullptr};
  fmi2Component c_ = nullptr;
};

std::string export_body(const std::filesystem::path& dir, const std::string& file, fmi::Interface interface) {
  exploration::Scenario s = exploration::default_scenario();
  s.body.kind = exploration::BodyKind::intocps;
  const std::string path = (dir / file).string();
  fmi::write_fmu(fmi::fmu_setup(fmi::Kind::body, s, interface), path);
  return path;
}

void expect_every_profile_bit_for_bit(const std::string& fmu_path) {
  const FmuLibrary lib(fmu_path);
  const std::vector<Fixture> all = fixtures::fixtures();
  ASSERT_EQ(all.size(), 7u);
  for (const Fixture& f : all) {
    Driven d(lib, f, "body");
    for (std::size_t k = 0; k < f.rows.size(); ++k) ASSERT_EQ(d.row(k), "") << fmu_path;
  }
}

}  // namespace

TEST(IntocpsBodyFmu, TheThesisInterfacesBodyBlockGivesTheBinarysOutputsBitForBitThroughTheFmiApi) {
  const auto dir = swarmcheck::testing::fmi_scratch("intocps-body-thesis");
  const std::string path = export_body(dir, "Body_Block1.fmu", fmi::Interface::thesis);
  expect_every_profile_bit_for_bit(path);
  // Its variables are the Body_Block's: every parameter by its FMI name, inputs and outputs.
  const FmuLibrary lib(path);
  EXPECT_EQ(lib.description().model_name, "swarmcheck Body (thesis interface)");
  for (const exploration::IntocpsBodyParameter& d : exploration::intocps_body_parameters()) {
    const auto* v = lib.description().find(std::string(d.name));
    ASSERT_NE(v, nullptr) << d.name;
    EXPECT_EQ(v->causality, "parameter") << d.name;
    // The Body_Block's own start values (the thesis's multi-model sets the position and battery).
    EXPECT_EQ(v->start_number, exploration::intocps_parameter_value(exploration::IntocpsBodyParams{}, d)) << d.name;
  }
  for (const char* in : {"servo_left_input", "servo_right_input"}) EXPECT_EQ(lib.description().find(in)->causality, "input");
  for (const char* out : kOutputNames) EXPECT_EQ(lib.description().find(out)->causality, "output") << out;
  std::filesystem::remove_all(dir);
}

TEST(IntocpsBodyFmu, TheSwarmcheckInterfacesIntocpsBodyGivesTheBinarysOutputsBitForBitThroughTheFmiApi) {
  const auto dir = swarmcheck::testing::fmi_scratch("intocps-body-swarmcheck");
  const std::string path = export_body(dir, "Body.fmu", fmi::Interface::swarmcheck);
  expect_every_profile_bit_for_bit(path);
  const FmuLibrary lib(path);
  EXPECT_EQ(lib.description().model_name, "swarmcheck Body (intocps)");
  // Its start values are the scenario's body: the thesis's 1e21 J battery, robot 1's start.
  EXPECT_EQ(lib.description().find("battery_initial_energy")->start_number, 1e21);
  EXPECT_EQ(lib.description().find("initial_position[0]")->start_number, exploration::default_scenario().robots[0][0]);
  std::filesystem::remove_all(dir);
}

TEST(IntocpsBodyFmu, TwoInstancesInOneProcessEachGiveTheirOwnProfilesBits) {
  const auto dir = swarmcheck::testing::fmi_scratch("intocps-body-two");
  const FmuLibrary lib(export_body(dir, "Body_Block1.fmu", fmi::Interface::thesis));
  const std::vector<Fixture> all = fixtures::fixtures();
  Driven a(lib, all[2], "a"), b(lib, all[6], "b");   // 3-arc (its own start pose) and 8-random
  for (std::size_t k = 0; k < all[2].rows.size(); ++k) {
    ASSERT_EQ(a.row(k), "");
    ASSERT_EQ(b.row(k), "");
  }
  std::filesystem::remove_all(dir);
}
