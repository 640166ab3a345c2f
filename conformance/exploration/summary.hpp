#pragma once
// The summary of a run, as `swarmcheck run --json` prints it (without the "engine" key the verb
// adds). One definition for the command line and the harness, so that what the user sees is
// compared between the engines too, not only the step records.
#include "spec/exploration/types.hpp"
#include "spec/util/hana_json.hpp"

namespace swarmcheck::conformance::exploration {

// Sim: the model, the library, or a Simulation (the same accessors).
template <class Sim>
json_io::Json run_summary(const Sim& sim) {
  const swarmcheck::exploration::Scenario& s = sim.scenario();
  const auto completion = sim.completion_step();
  json_io::Json j = json_io::Json::object();
  j["completed"] = completion.has_value();
  j["completion_step"] = completion ? json_io::Json(*completion) : json_io::Json(nullptr);
  j["steps"] = sim.steps();
  j["planning_steps"] = sim.planning_steps();
  j["eP"] = sim.eP();
  j["sTime"] = sim.sTime();
  j["visited"] = sim.visited();
  j["free_cells"] = sim.free_cells();
  j["rule"] = json_io::enum_to_string(s.rule);
  j["mode"] = json_io::enum_to_string(s.mode);
  j["controller"] = json_io::enum_to_string(s.controller);   // they run in cosim mode only
  j["body"] = json_io::enum_to_string(s.body.kind);
  j["seed"] = s.seed;
  j["map_size"] = s.map_size;
  j["robots"] = s.robots.size();
  return j;
}

}  // namespace swarmcheck::conformance::exploration
