#pragma once
// A supervised multi-robot mission (DESIGN.md B3): robots with start positions, tasks (points),
// regions (axis-aligned rectangles, strict membership) and, for every event of the supervisor's
// FSM, its meaning: a robot starting a task (controllable) or a robot entering a region
// (uncontrollable). The mission file is JSON:
//
//   { "fsm": "control2.fsm",            path relative to the mission file
//     "initial_state": "s1", "marked_states": ["s134:146:143"],
//     "robots":  [{"name": "A", "start": [x, y]}, ...],
//     "tasks":   [{"name": "tsk1", "at": [x, y]}, ...],
//     "regions": [{"name": "reg5", "corners": [[x1, y1], [x2, y2]]}, ...],
//     "events":  {"a1s": {"robot": "A", "task": "tsk1"}, "a5e": {"robot": "A", "region": "reg5"}},
//     "about": "free text" }
//
// Optional: "world" (an occupancy grid of walls) and a robot's "radius" (metres, default 0), both
// in spec/mission/world.hpp. Without a world, a mission is an empty plane, as before.
//
// parse_mission_text only reads the JSON into a MissionDecl (types, unknown and missing keys);
// check_mission resolves every name against the declarations and the FSM and checks the mission
// before anything runs. Every problem is an InputError at "file: json.path".
#include <array>
#include <boost/hana.hpp>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "spec/supervisor/automaton.hpp"

namespace swarmcheck::mission {

using Point = std::array<double, 2>;  // [x, y] in metres

// ---- the file as written ---------------------------------------------------------------------

struct RobotDecl {
  BOOST_HANA_DEFINE_STRUCT(RobotDecl, (std::string, name), (Point, start));
};
struct TaskDecl {
  BOOST_HANA_DEFINE_STRUCT(TaskDecl, (std::string, name), (Point, at));
};
struct RegionDecl {
  BOOST_HANA_DEFINE_STRUCT(RegionDecl, (std::string, name), (std::array<Point, 2>, corners));
};
// A polygon obstacle (spec/mission/polygon.hpp): its corners in order, the closing edge implied.
struct ObstacleDecl {
  BOOST_HANA_DEFINE_STRUCT(ObstacleDecl, (std::vector<Point>, polygon));
};
// The robots' range sensor (spec/mission/sensing.hpp).
struct SensorDecl {
  BOOST_HANA_DEFINE_STRUCT(SensorDecl,
      (std::size_t, beams),
      (double, range_m),
      (double, noise_m));
};
// The occupancy grid (spec/mission/world.hpp): '#' occupied, '.' free, first row on top; or a
// free grid of size_m; either with polygon obstacles rasterised onto it. unknown_obstacles are
// in the world but not on the robots' map (spec/mission/sensing.hpp).
struct WorldDecl {
  BOOST_HANA_DEFINE_STRUCT(WorldDecl,
      (double, resolution_m),
      (Point, origin),                     // the grid's lower-left corner
      (std::optional<std::vector<std::string>>, rows),
      (std::optional<Point>, size_m),      // [width, height]: when there are no rows
      (std::optional<std::vector<ObstacleDecl>>, obstacles),
      (std::optional<std::vector<ObstacleDecl>>, unknown_obstacles),
      (std::optional<SensorDecl>, sensor));
};
struct MeaningDecl {
  BOOST_HANA_DEFINE_STRUCT(MeaningDecl,
      (std::string, robot),
      (std::optional<std::string>, task),
      (std::optional<std::string>, region));
};
struct MissionDecl {
  BOOST_HANA_DEFINE_STRUCT(MissionDecl,
      (std::optional<std::string>, about),
      (std::string, fsm),
      (std::string, initial_state),
      (std::vector<std::string>, marked_states),
      (std::vector<RobotDecl>, robots),
      (std::vector<TaskDecl>, tasks),
      (std::vector<RegionDecl>, regions),
      (std::optional<WorldDecl>, world));
  std::map<std::string, MeaningDecl> events;  // "events" is an object keyed by event name
  // robots[i].radius, metres (read apart, so that RobotDecl keeps its two fields); 0 when absent.
  std::vector<double> radii;
};

// Reads the JSON text; `file` names it in messages ("file:line:col" for syntax errors).
MissionDecl parse_mission_text(const std::string& text, const std::string& file);

// ---- the checked mission -----------------------------------------------------------------------

struct Robot {
  std::string name;
  Point start;
  double radius = 0.0;  // metres; only a world's obstacles see it
};
struct Task {
  std::string name;
  Point at;
};
struct Region {
  std::string name;
  Point lo, hi;  // lo[k] < hi[k]; a point p is inside iff lo[k] < p[k] < hi[k] for k = 0, 1
};

// The checked occupancy grid (spec/mission/world.hpp has its geometry and the path planner).
struct GridWorld {
  double resolution_m = 1.0;
  Point origin{};                  // lower-left corner
  std::size_t rows = 0, cols = 0;  // both > 0
  std::vector<char> occupied;      // row-major, row 0 on top
  std::vector<std::vector<Point>> polygons;    // the obstacles rasterised into `occupied`
  // Unknown obstacles (spec/mission/sensing.hpp): cells occupied in the world but not on the
  // map `occupied` (empty: none), and their polygons; the robots' range sensor.
  std::vector<char> hidden;
  std::vector<std::vector<Point>> unknown_polygons;
  std::size_t sensor_beams = 64;
  double sensor_range_m = 3.0;
  double sensor_noise_m = 0.0;
  std::vector<std::vector<char>> traversable;  // per robot, traversable_cells for its radius
};

enum class MeaningKind { task_start, region_entry };
struct Meaning {
  MeaningKind kind;
  std::size_t robot;   // index into Mission::robots
  std::size_t target;  // index into tasks (task_start) or regions (region_entry)
  friend bool operator==(const Meaning&, const Meaning&) = default;
};

struct Mission {
  std::string source;                         // the mission file, for messages
  std::string fsm_name;                       // the "fsm" entry as written
  supervisor::Automaton fsm;
  std::string initial_state;
  std::vector<std::string> marked_states;     // non-empty, each a state of fsm
  std::vector<Robot> robots;
  std::vector<Task> tasks;
  std::vector<Region> regions;
  std::optional<GridWorld> world;             // none: an empty plane (no obstacles)
  std::map<std::string, Meaning> events;      // exactly the events of fsm
  // Meanings given for events the FSM does not have: checked, then ignored (the supervisor does
  // not observe them, so they constrain nothing and fire nothing).
  std::vector<std::string> unused_events;
};

// Resolves and checks `d` against `fsm` (read from the file d.fsm names). Checks, in order:
// at least one robot; names unique within robots, tasks and regions; radii >= 0; every region
// has two corners with different x and different y; the world's grid and its size for each
// radius (spec/mission/world.hpp); initial and marked states exist; every meaning names one
// robot and exactly one of a task or a region, all existing; every FSM event has a meaning
// (meanings of events the FSM lacks are kept aside in unused_events); task starts are
// controllable and region entries uncontrollable in the FSM; the world's checks (check_world:
// starts and tasks clear of walls, tasks and regions reachable); the region entries of the
// robots' start positions (fired at time 0, robot by robot, regions in file order) are enabled
// in turn from the initial state; some marked state is reachable from the initial state.
Mission check_mission(const MissionDecl& d, const supervisor::Automaton& fsm,
                      const std::string& file);

// The entry events fired at time 0: for each robot in order, each region (file order) that
// strictly contains its start and has an entry event for it. Names of events, in firing order.
std::vector<std::string> initial_entries(const Mission& m);

// ---- geometry ------------------------------------------------------------------------------------

// Straight-line distance, computed as sqrt(dx*dx + dy*dy) everywhere (so sums agree bit for bit).
double distance(const Point& a, const Point& b);
bool inside(const Region& g, const Point& p);  // strict

// The event whose meaning is (kind, robot, target), or nullptr.
const std::string* event_for(const Mission& m, MeaningKind kind, std::size_t robot,
                             std::size_t target);

}  // namespace swarmcheck::mission
