// swarmcheck fmu export: FMI 2.0 co-simulation FMUs of the Environment, the Controller and the
// Body, or the thesis's architecture as an INTO-CPS multi-model (fmi/export/fmu_export.hpp).
#include "apps/swarmcheck/fmu_verb.hpp"

#include <fmt/core.h>

#include <filesystem>

#include <memory>
#include <optional>

#include "apps/swarmcheck/robot_options.hpp"
#include "apps/swarmcheck/verb.hpp"
#include "fmi/export/fmu_export.hpp"
#include "impl/io/atomic_file.hpp"
#include "spec/exploration/scenario.hpp"

namespace swarmcheck::cli {
namespace {

struct FmuExportOptions {
  std::string kind;
  std::optional<int32_t> robots;
  std::string scenario_path;
  std::string output;
  std::string intocps;
  std::string handshake = "flag";
  std::string interface = "swarmcheck";
  RobotChoiceOptions robots_choice;
};

int fmu_export(const FmuExportOptions& o) {
  namespace ex = swarmcheck::exploration;
  if (o.intocps.empty() == o.kind.empty())
    throw InputError("fmu export", "give a kind (environment, controller or body) with -o FILE.fmu, or --intocps DIR");
  if (!o.kind.empty() && o.output.empty()) throw InputError("fmu export", "-o FILE.fmu is required with a kind");
  if (!o.intocps.empty() && !o.output.empty()) throw InputError("fmu export", "-o goes with a kind; --intocps writes its own files");
  const fmi::Interface interface = o.interface == "thesis" ? fmi::Interface::thesis : fmi::Interface::swarmcheck;
  // The thesis interface stands in for the thesis's own FMUs: their start values and rule set
  // unless a scenario says otherwise.
  ex::Scenario s = !o.scenario_path.empty()                 ? ex::load_scenario(o.scenario_path)
                   : interface == fmi::Interface::thesis ? fmi::thesis_interface_scenario()
                                                          : ex::default_scenario();
  if (o.robots) s = fmi::scenario_with_robots(s, *o.robots);
  ex::ScenarioOverrides over;
  apply_robot_choices(o.robots_choice, "", over);
  if (interface == fmi::Interface::thesis && (over.controller || over.body))
    throw InputError(over.controller ? "--controller" : "--body",
                     "the thesis interface's Controller and Body are the thesis's (its UController's law, the 20-sim "
                     "body); --controller and --body go with --interface swarmcheck");
  s = ex::with_overrides(ex::ValidScenario(s), over);
  if (!o.intocps.empty()) {
    if (interface == fmi::Interface::thesis) {
      const fmi::ThesisProject p = fmi::write_intocps_thesis(s, o.intocps);
      fmt::print("wrote {}/: FMUs/Environment.fmu, UController.fmu, Body_Block1..{}.fmu, {}, {} (thesis A's published "
                 "INTO-CPS project, swarmcheck's FMUs)\n",
                 o.intocps, s.robots.size(), std::filesystem::relative(p.multimodel, o.intocps).string(),
                 std::filesystem::relative(p.config, o.intocps).string());
      fmt::print("run it: swarmcheck cosim {} --config {} -o outputs.csv\n", p.multimodel, p.config);
      return 0;
    }
    for (const char* name : {"Environment.fmu", "Controller.fmu", "Body.fmu", "multimodel.json", "coe.json"})
      io::refuse_output_that_is_an_input((std::filesystem::path(o.intocps) / name).string(), {o.scenario_path});
    fmi::write_intocps(s, o.handshake == "epoch" ? fmi::Handshake::epoch : fmi::Handshake::flag, o.intocps);
    fmt::print("wrote {}/: Environment.fmu, Controller.fmu, Body.fmu, multimodel.json, coe.json ({} robots, {} handshake, "
               "{} controller, {} body)\n",
               o.intocps, s.robots.size(), o.handshake, json_io::enum_to_string(s.controller),
               json_io::enum_to_string(s.body.kind));
    fmt::print("run it: swarmcheck cosim {}/multimodel.json --config {}/coe.json -o outputs.csv\n", o.intocps, o.intocps);
    return 0;
  }
  const fmi::Kind kind = o.kind == "environment" ? fmi::Kind::environment
                         : o.kind == "controller" ? fmi::Kind::controller
                                                  : fmi::Kind::body;
  io::refuse_output_that_is_an_input(o.output, {o.scenario_path});
  const fmi::FmuSetup setup = fmi::fmu_setup(kind, s, interface);
  fmi::write_fmu(setup, o.output);
  fmt::print("wrote {} ({}, {}, FMI 2.0 co-simulation, {} interface{})\n", o.output, fmi::model_identifier(kind),
             fmi::model_name(setup), o.interface,
             kind == fmi::Kind::environment ? fmt::format(", {} robots, {} obstacle cells", s.robots.size(), s.obstacles.size())
                                            : std::string());
  return 0;
}

}  // namespace

void add_fmu_verb(CLI::App& app, int& exit_code) {
  CLI::App* fmu = app.add_subcommand("fmu", "FMI 2.0 co-simulation FMUs of the exploration system");
  fmu->require_subcommand(1);
  auto opts = std::make_shared<FmuExportOptions>();
  CLI::App* cmd = fmu->add_subcommand(
      "export", "write an FMU (environment, controller or body), or the thesis multi-model with --intocps DIR");
  cmd->add_option("kind", opts->kind, "environment | controller | body")
      ->check(CLI::IsMember({"environment", "controller", "body"}));
  cmd->add_option("-o,--output", opts->output, "The .fmu file to write");
  cmd->add_option("--scenario", opts->scenario_path,
                  "Scenario file whose values are the parameters' start values (default: the built-in one)");
  cmd->add_option("--robots", opts->robots,
                  "Robots N (the Environment's variables are generated for N); the scenario's own robots when it "
                  "has N, else N spread over its free cells");
  cmd->add_option("--intocps", opts->intocps,
                  "Write Environment.fmu, Controller.fmu, Body.fmu, multimodel.json and coe.json into DIR; with "
                  "--interface thesis, thesis A's published INTO-CPS project (FMUs/, Multi-models/mm-new/mm.json, "
                  "its co-sim/coe.json) with swarmcheck's FMUs");
  cmd->add_option("--interface", opts->interface,
                  "swarmcheck (its variables) | thesis (the variables, Real handshake and file names of thesis A's "
                  "published FMUs, to drop into its INTO-CPS project; their start values and rule set thesis unless "
                  "--scenario says)")
      ->check(CLI::IsMember({"swarmcheck", "thesis"}))
      ->capture_default_str();
  add_robot_options(cmd, opts->robots_choice);
  cmd->add_option("--handshake", opts->handshake, "flag (the thesis's) | epoch, for --intocps")
      ->check(CLI::IsMember({"flag", "epoch"}))
      ->capture_default_str();
  cmd->callback([opts, &exit_code] { exit_code = guarded([&] { return fmu_export(*opts); }); });
}

}  // namespace swarmcheck::cli
