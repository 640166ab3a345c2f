// Reading the mission file's JSON into MissionDecl: syntax, types, unknown and missing keys.
#include "spec/mission/mission.hpp"

#include <cmath>
#include <initializer_list>
#include <utility>

#include "spec/util/hana_json.hpp"
#include "spec/util/json_text.hpp"
#include "spec/util/input_error.hpp"

namespace swarmcheck::mission {

namespace {

using json_io::Json;

// Every key in `keys` must be present in object `j` (its type is checked by from_json after).
void require_keys(const Json& j, const std::string& path,
                  std::initializer_list<std::pair<const char*, const char*>> keys) {
  if (!j.is_object())
    throw InputError(path.empty() ? "(top level)" : path,
                     "expected an object, got " + json_io::type_name(j));
  for (const auto& [key, what] : keys)
    if (!j.contains(key)) throw InputError(json_io::join_key(path, key), std::string("missing (") + what + ")");
}

void require_each(const Json& j, const char* list, const std::string& path,
                  std::initializer_list<std::pair<const char*, const char*>> keys) {
  if (!j.contains(list) || !j[list].is_array()) return;  // from_json reports the type
  for (std::size_t i = 0; i < j[list].size(); ++i)
    require_keys(j[list][i], json_io::join_index(path, i), keys);
}

// Coordinates within +-1e9 m (a million km): distances, path lengths and makespans summed from
// them stay finite and exact enough; 1e200 would square to infinity.
constexpr double kMaxCoordinate_m = 1e9;

void require_finite(const Point& p, const std::string& path) {
  if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || std::fabs(p[0]) > kMaxCoordinate_m ||
      std::fabs(p[1]) > kMaxCoordinate_m)
    throw InputError(path, "expected finite coordinates in metres, each within +-1e9");
}

MissionDecl decl_from_json(const Json& j) {
  require_keys(j, "", {{"fsm", "the path of the supervisor's .fsm file"},
                       {"initial_state", "the FSM state the mission starts in"},
                       {"marked_states", "the list of FSM states that complete the mission"},
                       {"robots", "a list of {\"name\", \"start\": [x, y]}"},
                       {"tasks", "a list of {\"name\", \"at\": [x, y]}"},
                       {"events", "an object giving each FSM event its meaning"}});
  require_each(j, "robots", "robots", {{"name", "the robot's name"}, {"start", "its start position [x, y]"}});
  require_each(j, "tasks", "tasks", {{"name", "the task's name"}, {"at", "its position [x, y]"}});
  require_each(j, "regions", "regions", {{"name", "the region's name"},
                              {"corners", "two opposite corners [[x1, y1], [x2, y2]]"}});
  if (j.contains("world"))
    require_keys(j["world"], "world",
                 {{"resolution_m", "the side of a grid cell in metres"},
                  {"origin", "the grid's lower-left corner [x, y]"}});
  for (const char* list : {"obstacles", "unknown_obstacles"})
    if (j.contains("world") && j["world"].contains(list))
      require_each(j["world"], list, std::string("world.") + list,
                   {{"polygon", "its corners in order [[x, y], ...]"}});
  if (j.contains("world") && j["world"].contains("sensor"))
    require_keys(j["world"]["sensor"], "world.sensor",
                 {{"beams", "the number of beams"}, {"range_m", "the range in metres"},
                  {"noise_m", "the readings' standard deviation in metres"}});
  MissionDecl d;
  Json rest = j;
  rest.erase("events");
  if (rest.contains("robots") && rest["robots"].is_array())
    for (std::size_t i = 0; i < rest["robots"].size(); ++i) {
      Json& robot = rest["robots"][i];
      double radius = 0.0;
      if (robot.contains("radius")) {
        json_io::from_json(robot["radius"], json_io::join_index("robots", i) + ".radius", radius);
        robot.erase("radius");
      }
      d.radii.push_back(radius);
    }
  json_io::from_json(rest, "", d);
  const Json& ev = j["events"];
  if (!ev.is_object())
    throw InputError("events", "expected an object keyed by event name, got " +
                                   json_io::type_name(ev));
  for (auto it = ev.begin(); it != ev.end(); ++it) {
    const std::string path = "events." + it.key();
    require_keys(it.value(), path, {{"robot", "the robot the event belongs to"}});
    MeaningDecl m;
    json_io::from_json(it.value(), path, m);
    d.events.emplace(it.key(), m);
  }
  for (std::size_t i = 0; i < d.robots.size(); ++i)
    require_finite(d.robots[i].start, json_io::join_index("robots", i) + ".start");
  for (std::size_t i = 0; i < d.tasks.size(); ++i)
    require_finite(d.tasks[i].at, json_io::join_index("tasks", i) + ".at");
  if (d.world) require_finite(d.world->origin, "world.origin");
  if (d.world)
    for (const auto& [list, name] : {std::pair{&d.world->obstacles, "world.obstacles"},
                                     std::pair{&d.world->unknown_obstacles, "world.unknown_obstacles"}})
      if (*list)
        for (std::size_t k = 0; k < (*list)->size(); ++k)
          for (std::size_t i = 0; i < (**list)[k].polygon.size(); ++i)
            require_finite((**list)[k].polygon[i],
                           json_io::join_index(json_io::join_index(name, k) + ".polygon", i));
  for (std::size_t i = 0; i < d.regions.size(); ++i)
    for (std::size_t k = 0; k < 2; ++k)
      require_finite(d.regions[i].corners[k],
                     json_io::join_index(json_io::join_index("regions", i) + ".corners", k));
  return d;
}

}  // namespace

MissionDecl parse_mission_text(const std::string& text, const std::string& file) {
  const auto j = json_io::parse_json_text(text, file);
  try {
    return decl_from_json(j);
  } catch (const InputError& e) {
    throw json_io::in_file(e, file);
  }
}

double distance(const Point& a, const Point& b) {
  const double dx = b[0] - a[0];
  const double dy = b[1] - a[1];
  return std::sqrt(dx * dx + dy * dy);
}

bool inside(const Region& g, const Point& p) {
  return g.lo[0] < p[0] && p[0] < g.hi[0] && g.lo[1] < p[1] && p[1] < g.hi[1];
}

const std::string* event_for(const Mission& m, MeaningKind kind, std::size_t robot,
                             std::size_t target) {
  for (const auto& [name, meaning] : m.events)
    if (meaning == Meaning{kind, robot, target}) return &name;
  return nullptr;
}

std::vector<std::string> initial_entries(const Mission& m) {
  std::vector<std::string> out;
  for (std::size_t r = 0; r < m.robots.size(); ++r)
    for (std::size_t g = 0; g < m.regions.size(); ++g)
      if (inside(m.regions[g], m.robots[r].start))
        if (const auto* e = event_for(m, MeaningKind::region_entry, r, g)) out.push_back(*e);
  return out;
}

}  // namespace swarmcheck::mission
