#pragma once
// --controller, --body and --preset: the robots' controller and body, and the named
// combinations of a rule set, a controller and a body (spec/exploration/robot_kinds.hpp), for
// every verb that takes a scenario. A flag overrides the scenario file; --rule, --controller and
// --body given beside --preset override the preset's.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "spec/exploration/robot_kinds.hpp"
#include "spec/exploration/scenario.hpp"

namespace swarmcheck::cli {

struct RobotChoiceOptions {
  std::string preset, controller, body;   // empty: as in the scenario
};

inline void add_robot_options(CLI::App* cmd, RobotChoiceOptions& o) {
  namespace ex = swarmcheck::exploration;
  std::vector<std::string> controllers, bodies, presets;
  std::string controller_help = "The robots' controller (overrides the file):", body_help = "The robots' body (overrides the file):",
              preset_help = "A named system:";
  for (const auto& row : ex::kControllers) {
    controllers.emplace_back(row.name);
    controller_help += " " + std::string(row.name) + ": " + std::string(row.summary) + ";";
  }
  for (const auto& row : ex::kBodies) {
    bodies.emplace_back(row.name);
    body_help += " " + std::string(row.name) + ": " + std::string(row.summary) + ";";
  }
  for (const auto& p : ex::kPresets) {
    presets.emplace_back(p.name);
    preset_help += " " + std::string(p.name) + ": " + std::string(p.summary) + ";";
  }
  controller_help.pop_back();
  body_help.pop_back();
  preset_help.pop_back();
  cmd->add_option("--controller", o.controller, controller_help)->check(CLI::IsMember(controllers));
  cmd->add_option("--body", o.body, body_help)->check(CLI::IsMember(bodies));
  cmd->add_option("--preset", o.preset, preset_help)->check(CLI::IsMember(presets));
}

// The overrides the options make; `rule` is --rule's value (empty if not given).
inline void apply_robot_choices(const RobotChoiceOptions& o, const std::string& rule,
                                swarmcheck::exploration::ScenarioOverrides& over) {
  namespace ex = swarmcheck::exploration;
  if (const ex::Preset* p = ex::find_preset(o.preset)) {
    over.rule = p->rule;
    over.controller = p->controller;
    over.body = p->body;
  }
  if (!rule.empty()) over.rule = json_io::enum_from_string<ex::RuleSet>(rule, "--rule");
  if (!o.controller.empty()) over.controller = json_io::enum_from_string<ex::ControllerKind>(o.controller, "--controller");
  if (!o.body.empty()) over.body = json_io::enum_from_string<ex::BodyKind>(o.body, "--body");
}

}  // namespace swarmcheck::cli
