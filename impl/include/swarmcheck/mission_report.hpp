#pragma once
// swarmcheck: the objects `swarmcheck mission plan --json` and `mission run --json` print, from the
// library's Plan and RunResult. One definition for the command line and the Python package
// (swarmcheck.mission_plan / mission_run return these dicts).
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "spec/mission/mission.hpp"
#include "spec/mission/plan.hpp"
#include "spec/mission/run.hpp"
#include "spec/util/hana_json.hpp"

namespace swarmcheck::mission {

// `file`: the mission file as named to the user; `planner`: exact or thesis; `from`: the state
// planned from.
inline json_io::Json mission_plan_report(const Mission& m, const Plan& p, const std::string& file,
                                         const std::string& planner, const std::string& from) {
  using Json = json_io::Json;
  const auto seqs = task_sequences(m, p.events);
  Json robots = Json::array();
  for (std::size_t r = 0; r < m.robots.size(); ++r) {
    Json tasks = Json::array();
    for (const auto t : seqs[r]) tasks.push_back(m.tasks[t].name);
    robots.push_back({{"name", m.robots[r].name},
                      {"tasks", tasks},
                      {"travel", p.found ? Json(p.cost.travel[r]) : Json(nullptr)}});
  }
  return {{"mission", file},       {"planner", planner}, {"from", from},
          {"found", p.found},      {"final_state", p.found ? Json(p.final_state) : Json(nullptr)},
          {"events", p.events},    {"robots", robots},
          {"makespan", p.found ? Json(p.cost.makespan) : Json(nullptr)},
          {"total", p.found ? Json(p.cost.total) : Json(nullptr)}};
}

// `body`: unicycle or kinematic, as the run was asked for.
inline json_io::Json mission_run_report(const Mission& m, const RunResult& r, const std::string& file,
                                        const std::string& body) {
  using Json = json_io::Json;
  std::vector<std::string> events;
  for (const auto& e : r.events) events.push_back(e.event);
  Json travel = Json::object();
  for (std::size_t k = 0; k < m.robots.size(); ++k) travel[m.robots[k].name] = r.travel[k];
  Json intervals = Json::array();
  for (const auto& i : r.intervals)
    intervals.push_back({{"robot", i.robot}, {"activity", json_io::enum_to_string(i.activity)},
                         {"from", i.from_s}, {"to", i.to_s}});
  return {{"mission", file},
          {"body", body},
          {"completed", r.completed},
          {"reason", r.reason},
          {"final_state", r.final_state},
          {"events", events},
          {"time", r.time_s},
          {"travel", travel},
          {"makespan_planned", r.makespan_planned},
          {"replans", r.replans},
          {"plan_cache_hits", r.plan_cache_hits},
          {"intervals", intervals},
          {"yields", r.yields},
          {"replans_sensed", r.replans_sensed},
          {"bumps", r.bumps},
          {"steers", r.steers},
          // least gap between two robots' disks over the run; null with one robot
          {"clearance_min_m", std::isfinite(r.clearance_min_m) ? Json(r.clearance_min_m) : Json()}};
}

}  // namespace swarmcheck::mission
