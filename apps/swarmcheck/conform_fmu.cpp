// swarmcheck conform --fmu FILE ...: the FMUs of system A under the harness.
#include "apps/swarmcheck/conform_fmu.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "conformance/fmu/fmu_conform.hpp"
#include "spec/exploration/scenario.hpp"
#include "spec/util/hana_json.hpp"
#include "spec/util/input_error.hpp"

namespace swarmcheck::cli {

namespace ex = swarmcheck::exploration;
namespace cf = swarmcheck::conformance::fmu;

void add_conform_fmu_options(CLI::App* cmd, ConformFmuArgs& a) {
  cmd->add_option("--fmu", a.fmus,
                  "An FMU of your own to check against the model: a Controller or a Body alone (driven with generated "
                  "inputs), or the Environment, the Controller and the Body (three --fmu FILE, any order: they are told "
                  "apart by their variables; cases have the Environment's robot and obstacle counts). Every output is "
                  "compared every step")
      ->take_all();
  cmd->add_option("--interface", a.interface,
                  "With --fmu: whose variable names the FMUs have: swarmcheck | thesis (thesis A's published FMUs')")
      ->check(CLI::IsMember({"swarmcheck", "thesis"}))
      ->capture_default_str();
  cmd->add_option("--rule", a.rule, "With --fmu: the rule set of every case (default: each case draws one)")
      ->check(CLI::IsMember({"thesis", "deterministic", "stochastic"}));
  add_robot_options(cmd, a.robots);
  cmd->add_option("--tolerance", a.tolerance,
                  "With --fmu: absolute tolerance of a comparison (default 0 with --relative-tolerance 0: the same bits)");
  cmd->add_option("--relative-tolerance", a.relative_tolerance, "With --fmu: relative tolerance (times |model value|)");
}

int conform_fmu(const ConformFmuArgs& a, int cases, bool cases_given, uint64_t seed, int64_t max_steps,
                const std::string& out_dir, double case_time_limit_s, bool json) {
  cf::FmuConformOptions o;
  if (a.fmus.size() != 1 && a.fmus.size() != 3)
    throw InputError("--fmu", "expected one FMU (a Controller or a Body) or three (Environment, Controller, Body), got " +
                                  std::to_string(a.fmus.size()));
  o.environment = a.fmus[0];   // the roles are read from the files' variables
  if (a.fmus.size() == 3) {
    o.controller = a.fmus[1];
    o.body = a.fmus[2];
  }
  o.interface = a.interface == "thesis" ? cf::FmuInterface::thesis : cf::FmuInterface::swarmcheck;
  ex::ScenarioOverrides over;
  apply_robot_choices(a.robots, a.rule, over);
  // The thesis interface's FMUs are the thesis's controller and 20-sim body unless told otherwise.
  o.controller_law = over.controller.value_or(o.interface == cf::FmuInterface::thesis ? ex::ControllerKind::thesis
                                                                                      : ex::ControllerKind::swarmcheck);
  o.body_kind = over.body.value_or(o.interface == cf::FmuInterface::thesis ? ex::BodyKind::intocps : ex::BodyKind::kinematic);
  o.rule = over.rule;
  o.cases = cases_given ? cases : 30;
  o.seed = seed;
  o.max_steps = max_steps;
  o.out_dir = out_dir;
  o.quiet_limit = std::chrono::milliseconds(static_cast<int64_t>(case_time_limit_s * 1000));
  o.tolerance = {a.tolerance, a.relative_tolerance};
  const bool progress = ::isatty(2) == 1 && !json;
  if (progress) o.on_case = [](int done, int asked) { fmt::print(stderr, "\rconform --fmu: case {}/{}", done, asked); };
  const std::string compared =
      o.tolerance.bits() ? "by bits" : fmt::format("within {:g} + {:g} |model|", o.tolerance.absolute, o.tolerance.relative);
  const cf::FmuConformReport r = cf::run_fmu_conform(o);
  if (progress) fmt::print(stderr, "\n");
  const std::string model = fmt::format("rule {}, controller {}, body {}", a.rule.empty() ? "drawn per case" : a.rule,
                                        json_io::enum_to_string(o.controller_law), json_io::enum_to_string(o.body_kind));
  if (json) {
    nlohmann::ordered_json j;
    j["system"] = "fmu";
    j["checked"] = r.checked;
    j["robots"] = r.robots;
    j["obstacles"] = r.obstacles;
    j["interface"] = a.interface;
    j["model"] = model;
    j["compared"] = compared;
    j["cases_run"] = r.cases_run;
    j["agree"] = !r.counterexample;
    if (r.counterexample) {
      j["divergence"] = r.counterexample->divergence.describe();
      j["step"] = r.counterexample->divergence.step;
      j["shrinks"] = r.counterexample->shrinks;
      j["counterexample"] = r.counterexample->folder;
    }
    fmt::print("{}\n", j.dump());
    return r.counterexample ? 1 : 0;
  }
  if (r.checked == "loop")
    fmt::print("conform --fmu: Environment of {} robots and {} obstacle cells, {} interface; model: {}; compared {}\n",
               r.robots, r.obstacles, a.interface, model, compared);
  else
    fmt::print("conform --fmu: a {} FMU alone, driven with generated inputs; model: the {} {}; compared {}\n", r.checked,
               r.checked == "body" ? json_io::enum_to_string(o.body_kind) : json_io::enum_to_string(o.controller_law),
               r.checked, compared);
  if (!r.counterexample) {
    fmt::print("conform --fmu: {} cases agree (seed {})\n", r.cases_run, seed);
    return 0;
  }
  const cf::FmuCounterexample& cx = *r.counterexample;
  if (r.checked != "loop") {
    fmt::print("conform --fmu: case {} differs; shrunk {} times\n", r.cases_run, cx.shrinks);
    fmt::print("  {}\n", cx.divergence.describe());
    fmt::print("  counterexample: {}/ (case.json: the parameters and the inputs of each step; expected.csv: the model's "
               "outputs; divergence.json)\n",
               cx.folder);
    return 1;
  }
  fmt::print("conform --fmu: case {} differs; shrunk {} times to: map {}, {} robots, {} obstacles, rule {}, {} steps\n",
             r.cases_run, cx.shrinks, cx.minimal.map_size, cx.minimal.robots.size(), cx.minimal.obstacles.size(),
             json_io::enum_to_string(cx.minimal.rule), cx.minimal.max_steps);
  fmt::print("  {}\n", cx.divergence.describe());
  fmt::print("  counterexample: {}/ (README.txt, divergence.json, scenario.json)\n", cx.folder);
  fmt::print("  replay: swarmcheck cosim {}/multimodel.json --config {}/coe.json -o outputs.csv\n", cx.folder, cx.folder);
  return 1;
}

}  // namespace swarmcheck::cli
