#pragma once
// swarmcheck: a run driven to its end as `swarmcheck run` drives it (stopped as stalled when no
// robot can reach a new cell, or after a window of steps without one) and its summary, the object
// `swarmcheck run --json` prints. One definition for the command line, the conformance harness
// (both engines' summaries compared) and the Python package (`swarmcheck.run` returns this dict).
//
//   swarmcheck::exploration::Exploration run(s);
//   const auto end = swarmcheck::exploration::run_to_end(run, reachability(s), 100000, [](auto&, bool) {});
//   std::puts(swarmcheck::exploration::run_report(run, end, "impl").dump().c_str());
//
// Sim: the library's Exploration, the reference model, or the harness's Simulation (the same
// accessors).
#include <cstdint>
#include <string>
#include <utility>

#include "spec/exploration/neighbourhood.hpp"
#include "spec/exploration/reachability.hpp"
#include "spec/exploration/types.hpp"
#include "spec/util/hana_json.hpp"

namespace swarmcheck::exploration {

// The counters of a run (without the keys run_report adds).
template <class Sim>
json_io::Json run_summary(const Sim& sim) {
  const Scenario& s = sim.scenario();
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

// How a run ended, beyond the summary's counters.
struct RunEnd {
  Reachability reach;
  std::string outcome;        // completed | max_steps | stalled
  std::string stall_reason;   // empty unless stalled
};

// Steps `sim` until it is done or stalled: every reachable free cell visited while some are
// unreachable, or `stall_window` steps (0: never) without a newly visited cell. After every step
// on_step(sim, last) is called, `last` true after the final one (it may throw to stop the run:
// the exception leaves this function, the simulation as the last step left it).
template <class Sim, class OnStep>
RunEnd run_to_end(Sim& sim, Reachability reach, int64_t stall_window, OnStep&& on_step) {
  RunEnd end{reach, {}, {}};
  int64_t last_visited = sim.visited(), last_progress_step = sim.steps();
  while (!sim.done()) {
    sim.step();
    if (sim.visited() != last_visited) {
      last_visited = sim.visited();
      last_progress_step = sim.steps();
    }
    if (!sim.completion_step() && end.reach.unreachable_free_cells > 0 && sim.visited() >= end.reach.reachable_free_cells)
      end.stall_reason = "every reachable free cell is visited; " + std::to_string(end.reach.unreachable_free_cells) +
                         " free cells are unreachable";
    else if (stall_window > 0 && sim.steps() - last_progress_step >= stall_window)
      end.stall_reason = "no newly visited cell in the last " + std::to_string(stall_window) + " steps (--stall-window)";
    const bool last = sim.done() || !end.stall_reason.empty();
    on_step(sim, last);
    if (last) break;
  }
  end.outcome = sim.completion_step() ? "completed" : !end.stall_reason.empty() ? "stalled" : "max_steps";
  return end;
}

// The object `swarmcheck run --json` prints: the summary, the engine, how the run ended and the
// exploration percentage of the reachable cells.
template <class Sim>
json_io::Json run_report(const Sim& sim, const RunEnd& end, const std::string& engine) {
  const int64_t reachable = end.reach.reachable_free_cells;
  json_io::Json j = run_summary(sim);
  j["engine"] = engine;
  j["outcome"] = end.outcome;
  j["reachable_cells"] = reachable;
  j["unreachable_cells"] = end.reach.unreachable_free_cells;
  j["eP_reachable"] = reachable > 0 ? exploration_percent(sim.visited(), reachable) : 100.0;
  if (!end.stall_reason.empty()) j["stalled"] = end.stall_reason;
  return j;
}

}  // namespace swarmcheck::exploration
