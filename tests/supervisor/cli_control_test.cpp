// `swarmcheck fsm controllable|observable|project`, synth with `uo` events, and attributes
// pooled across the files of one command, driven through CLI11 as main.cpp wires them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "apps/swarmcheck/fsm_verb.hpp"
#include "impl/supervisor/fsm_io.hpp"
#include "tests/util/cli_runner.hpp"

namespace {

namespace fs = std::filesystem;
const std::string kThesisDir = SWARMCHECK_SCENARIOS "/thesis";
using swarmcheck::testing::CliRun;

CliRun fsm_cli(const std::vector<std::string>& args) {
  return swarmcheck::testing::run_verb(swarmcheck::cli::add_fsm_verb, args);
}

fs::path scratch() {
  const fs::path d = fs::temp_directory_path() / ("swarmcheck_cli_control_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

std::string write(const std::string& name, const std::string& text) {
  const fs::path p = scratch() / name;
  std::ofstream(p) << text;
  return p.string();
}

std::vector<std::string> thesis_plant() {
  std::vector<std::string> out;
  for (const char* f : {"region_a.fsm", "tasks_a.fsm", "region_b.fsm", "tasks_b.fsm"})
    out.push_back(kThesisDir + "/components/" + f);
  return out;
}

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

TEST(FsmControlCli, ThesisControl2VerdictOnBothEngines) {
  auto args = with({"fsm", "controllable", "--plant"}, thesis_plant());
  args = with(args, {"--sup", kThesisDir + "/control2.fsm", "--json"});
  const CliRun r = fsm_cli(args);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["plant_states"], 1848);
  EXPECT_EQ(j["supervisor_states"], 72);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_EQ(j["controllable"], false);
  EXPECT_EQ(j["witness"], nlohmann::json({"b8e", "b3s"}));
  EXPECT_EQ(j["disabled_event"], "b7e");
  EXPECT_EQ(j["nonblocking"], false);
  EXPECT_EQ(fsm_cli(with(args, {"--engine", "model"})).out, r.out);
}

const std::string kPlant = "2\np0 0 1\nu p1 uc o\np1 1 1\na p0 c o\n";

TEST(FsmControlCli, ASpecificationEventWithoutAttributesTakesThePlants) {
  const std::string plant = write("plant.fsm", kPlant);
  const std::string spec = write("spec.fsm", "2\ns0 0 1\nu s1\ns1 1 1\na s0\n");
  const std::string out = (scratch() / "sup.fsm").string();
  for (const char* engine : {"impl", "model"}) {
    const CliRun r = fsm_cli({"fsm", "synth", "--plant", plant, "--spec", spec, "-o", out, "--json",
                              "--engine", engine});
    ASSERT_EQ(r.status, 0) << r.err;
    const auto sup = swarmcheck::impl::supervisor::read_fsm_file(out);
    EXPECT_FALSE(sup.events.at("u").controllable);
    EXPECT_TRUE(sup.events.at("a").controllable);
  }
  const CliRun c = fsm_cli({"fsm", "controllable", "--plant", plant, "--sup", spec});
  EXPECT_EQ(c.status, 0) << c.err << c.out;
}

TEST(FsmControlCli, APlantEventWithoutAttributesTakesTheSpecifications) {
  const std::string plant = write("plant_bare.fsm", "2\np0 0 1\nu p1\np1 1 1\na p0\n");
  const std::string spec = write("spec_uc.fsm", "1\ns0 1 1\na s0 c o\nEVENTS\nu uc uo\n");
  const CliRun r = fsm_cli({"fsm", "controllable", "--plant", plant, "--sup", spec, "--json"});
  ASSERT_EQ(r.status, 1) << r.err;   // u is uncontrollable, and the supervisor never allows it
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["witness"], nlohmann::json::array());
  EXPECT_EQ(j["disabled_event"], "u");
}

TEST(FsmControlCli, AttributesStatedDifferentlyNameBothFilesAndLines) {
  const std::string plant = write("plant2.fsm", kPlant);
  const std::string spec = write("spec_c.fsm", "2\ns0 0 1\nu s1 c\ns1 1 0\n");
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"fsm", "synth", "--plant", plant, "--spec", spec, "-o",
                                 (scratch() / "never.fsm").string()},
        std::vector<std::string>{"fsm", "controllable", "--plant", plant, "--sup", spec}}) {
    const CliRun r = fsm_cli(args);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "swarmcheck: error: " + spec + ":3:6: event 'u' is c here but uc at " + plant +
                         ":3:6\n");
    EXPECT_EQ(r.out, "");
  }
  EXPECT_FALSE(fs::exists(scratch() / "never.fsm"));
}

TEST(FsmControlCli, ControllableGivesTheWitnessAndTheBlockingWordAndExitsOne) {
  const std::string plant = write("p3.fsm", "3\np0 0 1\na p1 c o\np1 0 1\nu p2 uc o\np2 1 0\n");
  const std::string sup = write("s3.fsm", "2\ns0 0 1\na s1 c o\ns1 0 0\nEVENTS\nu uc o\n");
  const CliRun r = fsm_cli({"fsm", "controllable", "--plant", plant, "--sup", sup});
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("controllable: no\n  after a, the plant can do the uncontrollable event u, "
                       "which the supervisor disables\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("nonblocking closed loop: no\n  after the empty word"), std::string::npos) << r.out;
}

const std::string kFaultPlant = "4\np0 1 2\nf p1 uc uo\na p2 c o\np1 1 1\na p3 c o\np2 1 0\np3 1 0\n";
const std::string kFaultSpec = "3\ns0 1 2\nf s1\na s2\ns1 1 0\ns2 1 0\n";

TEST(FsmControlCli, ObservableFindsTwoWordsThatLookAlike) {
  const std::string plant = write("fp.fsm", kFaultPlant);
  const std::string spec = write("fs.fsm", kFaultSpec);
  const std::vector<std::string> args{"fsm", "observable", "--plant", plant, "--spec", spec, "--json"};
  const CliRun r = fsm_cli(args);
  ASSERT_EQ(r.status, 1) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["word"], nlohmann::json::array());
  EXPECT_EQ(j["twin"], nlohmann::json({"f"}));
  EXPECT_EQ(j["event"], "a");
  EXPECT_EQ(j["unobservable_events"], nlohmann::json({"f"}));
  EXPECT_EQ(fsm_cli(with(args, {"--engine", "model"})).out, r.out);
}

TEST(FsmControlCli, SynthWithUnobservableEventsGivesTheNormalSupervisorOnBothEngines) {
  const std::string plant = write("fp2.fsm", kFaultPlant);
  const std::string spec = write("fs2.fsm", kFaultSpec);
  std::string bytes[2];
  int i = 0;
  for (const char* engine : {"impl", "model"}) {
    const std::string out = (scratch() / (std::string("normal_") + engine + ".fsm")).string();
    const CliRun r = fsm_cli({"fsm", "synth", "--plant", plant, "--spec", spec, "-o", out, "--json",
                              "--engine", engine});
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["normal"], true);
    EXPECT_EQ(j["unobservable_events"], nlohmann::json({"f"}));
    EXPECT_EQ(j["states"], 2);
    std::ifstream in(out);
    bytes[i++] = std::string(std::istreambuf_iterator<char>(in), {});
  }
  EXPECT_EQ(bytes[0], bytes[1]);
}

TEST(FsmControlCli, ProjectWritesTheObserver) {
  const std::string plant = write("fp3.fsm", kFaultPlant);
  const CliRun r = fsm_cli({"fsm", "project", plant});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto obs = swarmcheck::impl::supervisor::read_fsm(r.out, "stdout");
  EXPECT_EQ(obs.states, (std::vector<std::string>{"{p0,p1}", "{p2,p3}"}));
  EXPECT_EQ(obs.events.count("f"), 0u);
  const std::string out = (scratch() / "obs.fsm").string();
  const CliRun w = fsm_cli({"fsm", "project", plant, "-o", out, "--json"});
  ASSERT_EQ(w.status, 0) << w.err;
  EXPECT_EQ(nlohmann::json::parse(w.out)["erased_events"], nlohmann::json({"f"}));
  EXPECT_EQ(swarmcheck::impl::supervisor::read_fsm_file(out), obs);
  // --json without -o: the observer would go where the summary goes; refused, not ignored.
  const CliRun both = fsm_cli({"fsm", "project", plant, "--json"});
  EXPECT_EQ(both.status, 2);
  EXPECT_NE(both.err.find("--json: goes with -o FILE"), std::string::npos) << both.err;
}

}  // namespace
