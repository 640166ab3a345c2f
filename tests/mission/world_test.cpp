// Missions in a world (issue 14): the occupancy grid's overlap rule, A* routes that keep clear of
// the walls, the world's checks, and the walled example mission run to completion by the library
// and the model alike, its trace replayed (no overlap with a wall or another robot, every event
// enabled when it fired).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstdlib>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>

#include "conformance/mission/differential.hpp"
#include "conformance/mission/generate.hpp"
#include "impl/mission/trace.hpp"
#include "spec/mission/separation.hpp"
#include "spec/mission/world.hpp"
#include "spec/util/hana_json.hpp"
#include "spec/util/input_error.hpp"
#include "swarmcheck/mission.hpp"
#include "tests/mission/edited_mission.hpp"
#include "tests/mission/replay.hpp"

namespace {

namespace sm = swarmcheck::mission;
namespace im = swarmcheck::impl::mission;
namespace cm = swarmcheck::conformance::mission;
using Json = nlohmann::ordered_json;
const std::string kWalls = SWARMCHECK_SCENARIOS "/examples/walls.json";
const bool kSeededWorld = [] { return ::setenv("RC_PARAMS", "seed=21 max_success=300", 0) == 0; }();

sm::GridWorld grid(double res, sm::Point origin, const std::vector<std::string>& rows) {
  sm::WorldDecl d;
  d.resolution_m = res;
  d.origin = origin;
  d.rows = rows;
  return sm::build_world(d);
}

// True when some point of the polyline from `from` through the route's waypoints overlaps an
// obstacle for `radius` (200 samples a segment, both ends included).
bool route_touches(const sm::GridWorld& w, const sm::Point& from, const sm::Route& r,
                   double radius) {
  sm::Point a = from;
  for (const auto& b : r.waypoints) {
    for (int k = 0; k <= 200; ++k) {
      const double s = k / 200.0;
      if (sm::overlaps_obstacle(w, {a[0] + (b[0] - a[0]) * s, a[1] + (b[1] - a[1]) * s}, radius))
        return true;
    }
    a = b;
  }
  return false;
}

TEST(MissionWorld, OverlapIsTheDiskAgainstOccupiedSquaresAndTheGridsBorder) {
  // 4 x 4 cells of 1 m from (0, 0); the occupied cell is [1, 2] x [2, 3].
  const auto w = grid(1.0, {0, 0}, {"....", ".#..", "....", "...."});
  EXPECT_TRUE(sm::overlaps_obstacle(w, {1.5, 2.5}, 0.0));
  EXPECT_FALSE(sm::overlaps_obstacle(w, {1.0, 2.5}, 0.0));   // on its edge: touching only
  EXPECT_TRUE(sm::overlaps_obstacle(w, {0.95, 2.5}, 0.1));
  EXPECT_FALSE(sm::overlaps_obstacle(w, {0.85, 2.5}, 0.1));
  EXPECT_TRUE(sm::overlaps_obstacle(w, {0.9, 1.9}, 0.2));    // near its corner
  EXPECT_FALSE(sm::overlaps_obstacle(w, {0.5, 0.5}, 0.5));   // touches the border
  EXPECT_TRUE(sm::overlaps_obstacle(w, {0.5, 0.5}, 0.6));
  EXPECT_TRUE(sm::overlaps_obstacle(w, {-0.1, 0.5}, 0.0));   // outside the grid
}

TEST(MissionWorld, RouteGoesAroundAWallKeepsClearAndIsDeterministic) {
  // 5 m x 6 m; a wall from the bottom border up to 2 m below the top one.
  const auto w = grid(0.5, {0, 0}, {"..........", "..........", "..........", "..........",
                                    "....#.....", "....#.....", "....#.....", "....#.....",
                                    "....#.....", "....#.....", "....#.....", "....#....."});
  const auto trav = sm::traversable_cells(w, 0.2);
  const sm::Point from{1.0, 1.5}, to{4.0, 1.5};
  const auto r = sm::route_to_point(w, trav, from, to);
  ASSERT_TRUE(r.has_value());
  EXPECT_GT(r->length_m, sm::distance(from, to) + 2.0);  // the wall ends 1 m from the top
  EXPECT_EQ(r->waypoints.back(), to);
  EXPECT_FALSE(route_touches(w, from, *r, 0.2));
  const auto again = sm::route_to_point(w, trav, from, to);
  EXPECT_EQ(again->waypoints, r->waypoints);
  // A radius too large for the 2 m gap above the wall (the border is a wall too): no route.
  EXPECT_FALSE(sm::route_to_point(w, sm::traversable_cells(w, 0.6), from, to).has_value());
}

// Random grids of up to four walls (rectangles of cells), radii and traversable end cells: a
// route, when there is one, never brings the robot's disk onto a wall, and is no shorter than
// the straight line.
RC_GTEST_PROP(MissionWorld, RoutesNeverOverlapObstaclesOnRandomGrids, ()) {
  const auto rows = *rc::gen::inRange<std::size_t>(6, 21);
  const auto cols = *rc::gen::inRange<std::size_t>(6, 21);
  const double res = *rc::gen::element(0.25, 0.5, 1.0);
  const double radius = *rc::gen::element(0.0, 0.1, 0.3);
  std::vector<std::string> text(rows, std::string(cols, '.'));
  for (int k = *rc::gen::inRange(0, 5); k > 0; --k) {
    const auto i = *rc::gen::inRange<std::size_t>(0, rows), j = *rc::gen::inRange<std::size_t>(0, cols);
    const auto h = *rc::gen::inRange<std::size_t>(1, rows / 2 + 1);
    const auto wd = *rc::gen::inRange<std::size_t>(1, cols / 2 + 1);
    for (std::size_t a = i; a < std::min(rows, i + h); ++a)
      for (std::size_t b = j; b < std::min(cols, j + wd); ++b) text[a][b] = '#';
  }
  const auto w = grid(res, {-1.0, 2.0}, text);
  const auto trav = sm::traversable_cells(w, radius);
  std::vector<std::size_t> free;
  for (std::size_t c = 0; c < trav.size(); ++c)
    if (trav[c]) free.push_back(c);
  RC_PRE(free.size() >= 2);
  const auto point_in = [&](std::size_t cell) {
    const sm::Point c = sm::cell_centre(w, cell);
    return sm::Point{c[0] + res * (*rc::gen::inRange(-45, 46)) / 100.0,
                     c[1] + res * (*rc::gen::inRange(-45, 46)) / 100.0};
  };
  const sm::Point from = point_in(free[*rc::gen::inRange<std::size_t>(0, free.size())]);
  const sm::Point to = point_in(free[*rc::gen::inRange<std::size_t>(0, free.size())]);
  const auto r = sm::route_to_point(w, trav, from, to);
  RC_CLASSIFY(r.has_value(), "connected");
  if (!r) return;
  RC_ASSERT(!route_touches(w, from, *r, radius));
  RC_ASSERT(r->length_m >= sm::distance(from, to) * (1 - 1e-12));
}

// The walled example, edited by `edit`: the message load_mission throws after "m.json: ", or ""
// when it loads.
std::string message_for(const swarmcheck::test::EditJson& edit) {
  return swarmcheck::test::message_of_edited("world_check", kWalls,
                                             SWARMCHECK_SCENARIOS "/examples/one-at-a-time.fsm", edit);
}

TEST(MissionWorld, BadWorldsGetOneMessageAtTheirJsonPath) {
  EXPECT_EQ(message_for([](Json&) {}), "");
  EXPECT_EQ(message_for([](Json& j) { j["robots"][0]["start"] = {-6.25, 0.25}; }),
            "robots[0].start: robot A (radius 0.2 m) at [-6.25, 0.25] overlaps an obstacle of the "
            "world or leaves its grid");
  EXPECT_EQ(message_for([](Json& j) { j["robots"][2]["start"] = {8.1, 4}; }),
            "robots[2].start: robot C (radius 0 m) at [8.1, 4] overlaps an obstacle of the world or "
            "leaves its grid");
  EXPECT_EQ(message_for([](Json& j) { j["tasks"][1]["at"] = {-6.25, 0.25}; }),
            "tasks[1].at: an obstacle of the world covers task t2 at [-6.25, 0.25] for robot A "
            "(radius 0.2 m), or the task is outside the grid");
  EXPECT_EQ(message_for([](Json& j) {
              for (auto& row : j["world"]["rows"]) row = row.get<std::string>().replace(8, 1, "#");
            }),
            "tasks[1].at: task t2 at [-6.5, -3] is unreachable for robot A (radius 0.2 m) from "
            "its start [0, 5]: no path of cells clear of the walls by its radius plus half a "
            "cell leads there");
  EXPECT_EQ(message_for([](Json& j) { j["regions"][0]["corners"] = {{-7.9, 0.1}, {-4.6, 0.4}}; }),
            "regions[0]: region regt1 is unreachable for robot A (radius 0.2 m) from its start "
            "[0, 5]: no cell of the region is clear of the walls by its radius plus half a cell "
            "and connected to the start");
  EXPECT_EQ(message_for([](Json& j) { j["world"]["rows"][3] = std::string(32, 'x'); }),
            "world.rows[3]: expected 32 characters (as rows[0]), each '.' (free) or '#' "
            "(occupied); got 32 characters, 'x' at column 0");
  EXPECT_EQ(message_for([](Json& j) { j["world"]["resolution_m"] = 0; }),
            "world.resolution_m: expected a cell side in metres, > 0 and at most 1e6; got 0");
  EXPECT_EQ(message_for([](Json& j) { j["robots"][1]["radius"] = -1; }),
            "robots[1].radius: expected a radius in metres, >= 0 and at most 1e6; got -1");
  EXPECT_EQ(message_for([](Json& j) { j["robots"][1]["radius"] = 1000; }),
            "robots[1].radius: a radius of 1000 m in a world of 24 x 32 cells of 0.5 m needs "
            "12318739200 neighbour checks to find its free cells; at most 268435456 (use larger "
            "cells or a smaller world)");
  EXPECT_EQ(message_for([](Json& j) { j["world"].erase("rows"); }),
            "world.rows: missing (the grid's rows, top first: '#' occupied, '.' free; or "
            "world.size_m, [width, height] in metres of a free grid)");
  EXPECT_EQ(message_for([](Json& j) { j["world"]["walls"] = 1; }).substr(0, 12), "world.walls:");
}

// The plan costs routes around the walls: each robot's planned travel is its route's length, and
// the makespan is longer than the straight lines would give.
TEST(MissionWorld, PlanCostsRoutesAroundTheWalls) {
  const auto m = sm::load_mission(kWalls);
  const sm::Plan p = sm::Planner(m).plan(sm::initial_query(m));
  ASSERT_TRUE(p.found);
  const auto tasks = sm::task_sequences(m, p.events);
  double straight_makespan = 0.0;
  for (std::size_t r = 0; r < m.robots.size(); ++r) {
    ASSERT_EQ(tasks[r], std::vector<std::size_t>{r}) << m.robots[r].name;  // A t1, B t2, C t3
    const sm::Point to = m.tasks[tasks[r][0]].at;
    const auto route = sm::route_to_point(*m.world, m.world->traversable[r], m.robots[r].start, to);
    ASSERT_TRUE(route.has_value());
    EXPECT_EQ(p.cost.travel[r], route->length_m) << m.robots[r].name;
    EXPECT_GT(route->length_m, sm::distance(m.robots[r].start, to) + 0.5) << m.robots[r].name;
    straight_makespan = std::max(straight_makespan, sm::distance(m.robots[r].start, to));
  }
  EXPECT_GT(p.cost.makespan, straight_makespan);
  EXPECT_EQ(sm::evaluate_path(m, sm::initial_query(m), p.events).cost, p.cost);
}

void walls_run(sm::BodyModel body) {
  const auto m = sm::load_mission(kWalls);
  const auto run = swarmcheck::test::run_traced(m, body);
  const auto& [o, r, t] = run;
  ASSERT_EQ(swarmcheck::test::unclean(m, run), "");  // events enabled, no robot on a wall
  std::size_t steps = 0;
  for (const auto& e : t.entries) {
    if (e.is_event) continue;
    ++steps;
    for (std::size_t a = 0; a < m.robots.size(); ++a)
      for (std::size_t b = 0; b < a; ++b)
        EXPECT_GT(sm::distance(e.step.positions[a], e.step.positions[b]),
                  m.robots[a].radius + m.robots[b].radius)
            << m.robots[a].name << " meets " << m.robots[b].name << " at t=" << e.step.time_s;
  }
  EXPECT_GT(steps, 100u);
  for (std::size_t k = 0; k < m.robots.size(); ++k)  // every robot drove around a wall
    EXPECT_GT(r.travel[k], 4.0) << m.robots[k].name;
}

TEST(MissionWorld, WalledMissionCompletesWithoutCollisionAndModelAgreesKinematic) {
  walls_run(sm::BodyModel::kinematic);
}

TEST(MissionWorld, WalledMissionCompletesWithoutCollisionAndModelAgreesUnicycle) {
  walls_run(sm::BodyModel::unicycle);
}

// The differential in a world: run_case's missions (integer points, either body) in a grid of
// 0.5 m cells 3 m around them with up to three walls (bars of cells) and radii of 0..0.2 m; the
// cases the world's checks reject are discarded. With `unknown`, each bar is unknown (hidden
// from the map, for the sensor to find: spec/mission/sensing.hpp) with probability 1/2, and the
// sensor has 64 beams of 3 m with 0.02 m of noise.
cm::RunCase walled_case(bool unknown) {
  cm::RunCase c = *cm::run_case();
  sm::Mission& m = c.mission;
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  const auto add = [&](const sm::Point& p) {
    x0 = std::min(x0, p[0]), y0 = std::min(y0, p[1]), x1 = std::max(x1, p[0]), y1 = std::max(y1, p[1]);
  };
  for (const auto& r : m.robots) add(r.start);
  for (const auto& t : m.tasks) add(t.at);
  for (const auto& g : m.regions) add(g.lo), add(g.hi);
  const double res = 0.5;
  const auto cols = static_cast<std::size_t>((x1 - x0 + 6) / res);
  const auto rows = static_cast<std::size_t>((y1 - y0 + 6) / res);
  std::vector<std::string> text(rows, std::string(cols, '.'));
  std::vector<char> hidden(rows * cols, 0);
  for (int k = *rc::gen::inRange(0, 4); k > 0; --k) {
    const bool across = *rc::gen::arbitrary<bool>();
    const bool hide = unknown && *rc::gen::arbitrary<bool>();
    const auto i = *rc::gen::inRange<std::size_t>(0, rows), j = *rc::gen::inRange<std::size_t>(0, cols);
    const auto len = *rc::gen::inRange<std::size_t>(2, (across ? cols : rows) / 2 + 3);
    for (std::size_t n = 0; n < len; ++n) {
      const std::size_t a = across ? i : i + n, b = across ? j + n : j;
      if (a >= rows || b >= cols) continue;
      if (hide) hidden[a * cols + b] = 1;
      else text[a][b] = '#';
    }
  }
  m.world = grid(res, {x0 - 3, y0 - 3}, text);
  if (unknown) {
    for (std::size_t cell = 0; cell < hidden.size(); ++cell) hidden[cell] = hidden[cell] && !m.world->occupied[cell];
    m.world->hidden = hidden;
    m.world->sensor_noise_m = 0.02;
  }
  for (auto& r : m.robots) {
    r.radius = *rc::gen::element(0.0, 0.1, 0.2);
    m.world->traversable.push_back(sm::traversable_cells(*m.world, r.radius));
  }
  try {
    sm::check_world(m);
    sm::check_robots_apart(m);
  } catch (const swarmcheck::InputError&) {
    RC_DISCARD("the world's checks reject it");
  }
  return c;
}

RC_GTEST_PROP(MissionWorld, ImplRunEqualsModelRunOnGeneratedWalledMissions, ()) {
  const cm::RunCase c = walled_case(false);
  const sm::Mission& m = c.mission;
  bool detour = false;  // some robot's route to some task is 10 % longer than the straight line
  for (std::size_t r = 0; r < m.robots.size(); ++r)
    for (const auto& t : m.tasks)
      detour = detour || sm::travel_cost(m, r, m.robots[r].start, t.at) >
                             1.1 * sm::distance(m.robots[r].start, t.at);
  RC_CLASSIFY(detour, "a wall makes a detour");
  RC_TAG(swarmcheck::json_io::enum_to_string(c.options.body),
         sm::run_mission(m, c.options).reason.substr(0, 8));
  const auto d = cm::diff_run(m, c.options);
  RC_ASSERT(d.value_or("") == std::string());
}

// The same with unknown walls: the robots scan, re-route on what they sensed (or bumped into),
// and never overlap a wall (the runners would throw); the library and the model agree record for
// record.
RC_GTEST_PROP(MissionWorld, ImplRunEqualsModelRunAndNoRobotTouchesAnUnknownWallOnGeneratedMissions, ()) {
  const cm::RunCase c = walled_case(true);
  const sm::RunResult r = sm::run_mission(c.mission, c.options);
  RC_TAG(r.replans_sensed > 0 ? "re-routed on sensed cells" : "sensed nothing new",
         r.bumps > 0 ? "bumped" : "no bump", r.completed ? "complete" : r.reason.substr(0, 8));
  const auto d = cm::diff_run(c.mission, c.options);
  RC_ASSERT(d.value_or("") == std::string());
}

}  // namespace
