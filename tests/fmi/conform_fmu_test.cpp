// `conform --fmu` (conformance/fmu/fmu_conform.hpp): swarmcheck's exported FMUs agree with the
// model under it in both interfaces; FMUs built from the library with a fault in it are caught
// with a minimal counterexample folder that replays the divergence in swarmcheck's master; and a
// Body FMU that crashes or hangs is a counterexample, not the end of the campaign.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <bit>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "conformance/fmu/fmu_conform.hpp"
#include "fmi/export/fmu_export.hpp"
#include "fmi/master/master.hpp"
#include "impl/io/atomic_file.hpp"
#include "spec/exploration/scenario.hpp"
#include "spec/util/hana_json.hpp"
#include "spec/util/input_error.hpp"
#include "tests/fmi/scratch.hpp"
#include "tests/util/shell.hpp"

namespace {

using namespace swarmcheck;
namespace cf = swarmcheck::conformance::fmu;
namespace fm = swarmcheck::fmi::master;
namespace fs = std::filesystem;

struct Exported {
  fs::path dir;
  std::string environment, controller, body;
};

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// swarmcheck's three FMUs of the default scenario (4 robots, 4 obstacle cells); `library`, when
// given, is the FMUs' library with a fault built in, for the FMU of kind `faulty`.
Exported export_loop(const std::string& name, const std::string& library = "", fmi::Kind faulty = fmi::Kind::body) {
  Exported e;
  e.dir = swarmcheck::testing::fmi_scratch("conform-fmu-" + name);
  const exploration::Scenario s = exploration::default_scenario();
  const auto write = [&](fmi::Kind kind, const std::string& file) {
    const std::string path = (e.dir / file).string();
    const fmi::FmuSetup setup = fmi::fmu_setup(kind, s);
    io::write_file_atomically(path, !library.empty() && kind == faulty ? fmi::fmu_archive(setup, read_bytes(library))
                                                                         : fmi::fmu_archive(setup));
    return path;
  };
  e.environment = write(fmi::Kind::environment, "Environment.fmu");
  e.controller = write(fmi::Kind::controller, "Controller.fmu");
  e.body = write(fmi::Kind::body, "Body.fmu");
  return e;
}

cf::FmuConformOptions options(const Exported& e, int cases) {
  cf::FmuConformOptions o;
  o.environment = e.environment;
  o.controller = e.controller;
  o.body = e.body;
  o.cases = cases;
  o.max_steps = 150;
  o.out_dir = (e.dir / "out").string();
  return o;
}

}  // namespace

TEST(ConformFmu, SwarmchecksOwnFmusAgreeWithTheModelOnEveryCaseInTheSwarmcheckInterface) {
  const Exported e = export_loop("agree");
  const cf::FmuConformReport r = cf::run_fmu_conform(options(e, 25));
  EXPECT_EQ(r.robots, 4);
  EXPECT_EQ(r.obstacles, 4);
  EXPECT_EQ(r.cases_run, 25);
  EXPECT_FALSE(r.counterexample.has_value()) << r.counterexample->divergence.describe();
  fs::remove_all(e.dir);
}

TEST(ConformFmu, TheThesisInterfacesFmusAgreeWithTheModelUnderTheThesisControllerAndBody) {
  Exported e;
  e.dir = swarmcheck::testing::fmi_scratch("conform-fmu-thesis");
  const exploration::Scenario s = fmi::thesis_interface_scenario();
  e.environment = (e.dir / "Environment.fmu").string();
  e.controller = (e.dir / "UController.fmu").string();
  e.body = (e.dir / "Body_Block1.fmu").string();
  fmi::write_fmu(fmi::fmu_setup(fmi::Kind::environment, s, fmi::Interface::thesis), e.environment);
  fmi::write_fmu(fmi::fmu_setup(fmi::Kind::controller, s, fmi::Interface::thesis), e.controller);
  fmi::write_fmu(fmi::fmu_setup(fmi::Kind::body, s, fmi::Interface::thesis), e.body);
  cf::FmuConformOptions o = options(e, 8);
  o.interface = cf::FmuInterface::thesis;
  o.controller_law = exploration::ControllerKind::thesis;
  o.body_kind = exploration::BodyKind::intocps;
  o.max_steps = 60;
  const cf::FmuConformReport r = cf::run_fmu_conform(o);
  EXPECT_EQ(r.robots, 4);
  EXPECT_EQ(r.obstacles, 10);   // the thesis Environment's obstacle slots
  EXPECT_EQ(r.cases_run, 8);
  EXPECT_FALSE(r.counterexample.has_value()) << r.counterexample->divergence.describe();
  fs::remove_all(e.dir);
}

TEST(ConformFmu, ACatalogueFaultInTheEnvironmentFmuIsCaughtAndItsCounterexampleFolderReplaysTheDivergenceInTheMaster) {
  const Exported e = export_loop("blocked", FMU_FAULT_BLOCKED_FORGETS_OBSTACLES, fmi::Kind::environment);
  const cf::FmuConformReport r = cf::run_fmu_conform(options(e, 100));
  ASSERT_TRUE(r.counterexample.has_value());
  const cf::FmuCounterexample& cx = *r.counterexample;
  EXPECT_TRUE(cx.divergence.abnormal_end.empty()) << cx.divergence.abnormal_end;
  for (const char* f : {"multimodel.json", "coe.json", "scenario.json", "divergence.json", "README.txt"})
    EXPECT_TRUE(fs::exists(fs::path(cx.folder) / f)) << f;
  // The folder, run by the master as it is, ends on the step that differs, and there the variable
  // has the FMU's value; scenario.json is the minimal case (the model's side: swarmcheck run).
  fm::Master master(fm::read_multimodel(cx.folder + "/multimodel.json"), fm::read_config(cx.folder + "/coe.json"),
                    fm::Algorithm::jacobi);
  while (!master.done()) master.step();
  EXPECT_EQ(master.steps(), cx.divergence.step);
  EXPECT_EQ(std::bit_cast<uint64_t>(master.value(master.port(cx.divergence.variable))),
            std::bit_cast<uint64_t>(cx.divergence.fmu));
  const exploration::Scenario s = exploration::load_scenario(cx.folder + "/scenario.json");
  EXPECT_EQ(json_io::to_json(s), json_io::to_json(cx.minimal));
  // Minimal: the counterexample's case is no bigger than it has to be in its robots and obstacles
  // (fixed by the FMU) and ran to the divergence only.
  EXPECT_LE(cx.divergence.step, s.max_steps);
  // The README's commands run as they are: the model's side of the case.
  const auto run = swarmcheck::testing::run_binary(SWARMCHECK_BIN, "run " + cx.folder + "/scenario.json --json");
  EXPECT_EQ(run.status, 0) << run.out;
  fs::remove_all(e.dir);
}

// Everything the campaign unpacks or writes goes under TMPDIR: a folder of the test's own, which
// must be empty again after the campaign, whatever its children did (crashed, were killed).
struct OwnTmpdir {
  fs::path dir;
  explicit OwnTmpdir(const fs::path& d) : dir(d) {
    fs::create_directories(dir);
    ::setenv("TMPDIR", dir.c_str(), 1);
  }
  ~OwnTmpdir() { ::unsetenv("TMPDIR"); }
  bool empty() const { return fs::is_empty(dir); }
};

TEST(ConformFmu, ABodyFmuThatCrashesAtItsSeventhStepIsACounterexampleNamingTheSignal) {
  const Exported e = export_loop("crash", FMU_FAULT_BODY_CRASHES_AT_ITS_SEVENTH_STEP);
  const OwnTmpdir tmp(e.dir / "tmp");
  const cf::FmuConformReport r = cf::run_fmu_conform(options(e, 10));
  EXPECT_TRUE(tmp.empty()) << "the crashed cases left files in " << tmp.dir;
  ASSERT_TRUE(r.counterexample.has_value());
  EXPECT_NE(r.counterexample->divergence.abnormal_end.find("crashed with SIGSEGV"), std::string::npos)
      << r.counterexample->divergence.describe();
  EXPECT_TRUE(fs::exists(fs::path(r.counterexample->folder) / "multimodel.json"));
  // From the command line: status 1 (a counterexample), the signal and the replay command.
  const auto cli = swarmcheck::testing::run_binary(
      SWARMCHECK_BIN, "conform --fmu " + e.environment + " " + e.controller + " " + e.body + " --cases 5 --out " +
                          (e.dir / "cli-out").string());
  EXPECT_EQ(cli.status, 1) << cli.out;
  EXPECT_NE(cli.out.find("crashed with SIGSEGV"), std::string::npos) << cli.out;
  EXPECT_NE(cli.out.find("replay: swarmcheck cosim "), std::string::npos) << cli.out;
  fs::remove_all(e.dir);
}

TEST(ConformFmu, ABodyFmuThatHangsIsStoppedAtTheCaseTimeLimitAndIsACounterexample) {
  const Exported e = export_loop("hang", FMU_FAULT_BODY_HANGS_AT_ITS_SEVENTH_STEP);
  cf::FmuConformOptions o = options(e, 5);
  o.quiet_limit = std::chrono::milliseconds(500);
  const OwnTmpdir tmp(e.dir / "tmp");
  const cf::FmuConformReport r = cf::run_fmu_conform(o);
  EXPECT_TRUE(tmp.empty()) << "the killed cases left files in " << tmp.dir;
  ASSERT_TRUE(r.counterexample.has_value());
  EXPECT_NE(r.counterexample->divergence.abnormal_end.find("hung"), std::string::npos)
      << r.counterexample->divergence.describe();
  fs::remove_all(e.dir);
}

TEST(ConformFmu, FilesThatAreNotTheLoopAreRefusedWithTheFileNamed) {
  const Exported e = export_loop("refused");
  cf::FmuConformOptions o = options(e, 1);
  o.body = o.controller;   // two controllers, no body
  try {
    cf::run_fmu_conform(o);
    FAIL() << "two Controllers were accepted";
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("a second controller FMU"), std::string::npos) << err.what();
  }
  o.body = (e.dir / "missing.fmu").string();
  EXPECT_THROW(cf::run_fmu_conform(o), InputError);
  fs::remove_all(e.dir);
}

// One FMU alone: each of swarmcheck's Controller and Body FMUs, in both interfaces, driven with
// generated inputs, gives the spec's component step's outputs by bits.
TEST(ConformFmu, AControllerOrBodyFmuAloneAgreesWithTheSpecsComponentOnGeneratedInputs) {
  const auto dir = swarmcheck::testing::fmi_scratch("conform-fmu-alone");
  exploration::Scenario preset = exploration::default_scenario();
  preset.controller = exploration::ControllerKind::thesis;
  preset.body.kind = exploration::BodyKind::intocps;
  struct One {
    std::string file;
    fmi::FmuSetup setup;
    exploration::ControllerKind law;
    exploration::BodyKind body;
  };
  const exploration::Scenario s = exploration::default_scenario();
  const std::vector<One> fmus{
      {"Controller.fmu", fmi::fmu_setup(fmi::Kind::controller, s), exploration::ControllerKind::swarmcheck, exploration::BodyKind::kinematic},
      {"Body.fmu", fmi::fmu_setup(fmi::Kind::body, s), exploration::ControllerKind::swarmcheck, exploration::BodyKind::kinematic},
      {"UController.fmu", fmi::fmu_setup(fmi::Kind::controller, s, fmi::Interface::thesis), exploration::ControllerKind::thesis,
       exploration::BodyKind::intocps},
      {"Body_Block1.fmu", fmi::fmu_setup(fmi::Kind::body, s, fmi::Interface::thesis), exploration::ControllerKind::thesis,
       exploration::BodyKind::intocps},
      {"BodyIntocps.fmu", fmi::fmu_setup(fmi::Kind::body, preset), exploration::ControllerKind::thesis, exploration::BodyKind::intocps}};
  for (const One& one : fmus) {
    const std::string path = (dir / one.file).string();
    fmi::write_fmu(one.setup, path);
    cf::FmuConformOptions o;
    o.environment = path;
    o.controller_law = one.law;
    o.body_kind = one.body;
    o.cases = 40;
    o.max_steps = 80;
    o.out_dir = (dir / "out").string();
    const cf::FmuConformReport r = cf::run_fmu_conform(o);
    EXPECT_EQ(r.checked, one.setup.kind == fmi::Kind::body ? "body" : "controller") << one.file;
    EXPECT_EQ(r.cases_run, 40) << one.file;
    EXPECT_FALSE(r.counterexample.has_value()) << one.file << ": " << r.counterexample->divergence.describe();
  }
  // The model of the other controller differs at once: the campaign is not blind.
  cf::FmuConformOptions o;
  o.environment = (dir / "UController.fmu").string();
  o.controller_law = exploration::ControllerKind::swarmcheck;
  o.cases = 40;
  o.out_dir = (dir / "out").string();
  EXPECT_TRUE(cf::run_fmu_conform(o).counterexample.has_value());
  fs::remove_all(dir);
}

TEST(ConformFmu, ABodyFmuAloneThatCrashesAtItsSeventhStepShrinksToASevenStepCase) {
  const Exported e = export_loop("crash-alone", FMU_FAULT_BODY_CRASHES_AT_ITS_SEVENTH_STEP);
  const OwnTmpdir tmp(e.dir / "tmp");
  cf::FmuConformOptions o = options(e, 30);
  o.environment = e.body;
  o.controller.clear();
  o.body.clear();
  const cf::FmuConformReport r = cf::run_fmu_conform(o);
  EXPECT_TRUE(tmp.empty());
  ASSERT_TRUE(r.counterexample.has_value());
  EXPECT_NE(r.counterexample->divergence.abnormal_end.find("crashed with SIGSEGV at step 7"), std::string::npos)
      << r.counterexample->divergence.describe();
  const auto c = nlohmann::json::parse(std::ifstream(r.counterexample->folder + "/case.json"));
  EXPECT_EQ(c["servos"].size(), 7u);   // each case runs in a fresh process: the seventh step of the case
  EXPECT_TRUE(fs::exists(r.counterexample->folder + "/expected.csv"));
  fs::remove_all(e.dir);
}

TEST(ConformFmu, ATolerancesAcceptsWithinAbsolutePlusRelativeAndBitsOtherwise) {
  const cf::Tolerance bits;
  EXPECT_TRUE(bits.accepts(0.1, 0.1));
  EXPECT_FALSE(bits.accepts(0.0, -0.0));   // bits: -0.0 is not 0.0
  EXPECT_FALSE(bits.accepts(1.0, std::nextafter(1.0, 2.0)));
  const cf::Tolerance loose{1e-9, 1e-6};
  EXPECT_TRUE(loose.accepts(0.0, -0.0));
  EXPECT_TRUE(loose.accepts(1000.0, 1000.0 + 1e-3 + 1e-9 / 2));
  EXPECT_FALSE(loose.accepts(1000.0, 1000.0 + 2e-3));
  EXPECT_TRUE(loose.accepts(std::nan(""), std::nan("")));
  EXPECT_FALSE(loose.accepts(1.0, std::nan("")));
}
