#include "conformance/mission/counterexample.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "impl/io/atomic_file.hpp"
#include "spec/util/hana_json.hpp"
#include "swarmcheck/supervisor.hpp"

namespace swarmcheck::conformance::mission {

namespace {

namespace sm = swarmcheck::mission;
using Json = nlohmann::ordered_json;

Json meanings(const sm::Mission& m) {
  Json events = Json::object();
  for (const auto& [name, mn] : m.events) {
    Json j = {{"robot", m.robots[mn.robot].name}};
    if (mn.kind == sm::MeaningKind::task_start)
      j["task"] = m.tasks[mn.target].name;
    else
      j["region"] = m.regions[mn.target].name;
    events[name] = j;
  }
  return events;
}

// The world as a mission file declares it: the map's cells as rows (its polygons are already on
// them), the unknown obstacles as their polygons (rasterised again to the same hidden cells) and
// the sensor.
Json world_json(const sm::GridWorld& w) {
  Json rows = Json::array();
  for (std::size_t i = 0; i < w.rows; ++i) {
    std::string row(w.cols, '.');
    for (std::size_t j = 0; j < w.cols; ++j)
      if (w.occupied[i * w.cols + j]) row[j] = '#';
    rows.push_back(row);
  }
  Json j = {{"resolution_m", w.resolution_m}, {"origin", w.origin}, {"rows", rows}};
  if (!w.hidden.empty()) {
    Json unknown = Json::array();
    for (const auto& p : w.unknown_polygons) unknown.push_back({{"polygon", p}});
    j["unknown_obstacles"] = unknown;
  }
  j["sensor"] = {{"beams", w.sensor_beams}, {"range_m", w.sensor_range_m}, {"noise_m", w.sensor_noise_m}};
  return j;
}

}  // namespace

std::string mission_json(const sm::Mission& m, const std::string& fsm_file, const std::string& about) {
  Json robots = Json::array(), tasks = Json::array(), regions = Json::array();
  for (const auto& r : m.robots) {
    Json robot = {{"name", r.name}, {"start", r.start}};
    if (r.radius > 0) robot["radius"] = r.radius;
    robots.push_back(robot);
  }
  for (const auto& t : m.tasks) tasks.push_back({{"name", t.name}, {"at", t.at}});
  for (const auto& g : m.regions)
    regions.push_back({{"name", g.name}, {"corners", Json::array({g.lo, g.hi})}});
  Json j = {{"about", about},           {"fsm", fsm_file},
            {"initial_state", m.initial_state}, {"marked_states", m.marked_states},
            {"robots", robots},         {"tasks", tasks},
            {"regions", regions},       {"events", meanings(m)}};
  if (m.world) j["world"] = world_json(*m.world);
  return j.dump(2) + "\n";  // doubles in the shortest form that reads back to the same bits
}

Counterexample write_counterexample(const std::string& dir, const std::string& stem,
                                    const sm::Mission& m, const sm::RunOptions& o,
                                    const std::string& difference) {
  std::filesystem::create_directories(dir);
  Counterexample c;
  c.mission_path = dir + "/" + stem + ".json";
  c.fsm_path = dir + "/" + stem + ".fsm";
  // fmt's {} prints a double in the shortest form that reads back to the same bits.
  c.command = fmt::format("swarmcheck mission run {} --body {} --dt {} --max-time {} --speed {} --seed {}",
                          c.mission_path, json_io::enum_to_string(o.body), o.dt_s, o.max_time_s,
                          o.speed_m_per_s, o.seed);
  const std::string about = "counterexample of the mission harness; replay: " + c.command +
                            "; first difference: " + difference;
  swarmcheck::supervisor::write_fsm_file(c.fsm_path, m.fsm);
  impl::io::write_file_atomically(c.mission_path, mission_json(m, stem + ".fsm", about));
  return c;
}

}  // namespace swarmcheck::conformance::mission
