// Unknown obstacles and the range sensor (spec/mission/sensing.hpp): the scan's rule, the noise's
// key, the file's checks, and the unknown-wall example: the robot meets a wall its map does not
// have, re-routes on what it sensed and completes without touching it, library and model alike.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "conformance/mission/differential.hpp"
#include "spec/mission/sensing.hpp"
#include "spec/mission/world.hpp"
#include "swarmcheck/mission.hpp"
#include "tests/mission/edited_mission.hpp"
#include "tests/mission/replay.hpp"

namespace {

namespace sm = swarmcheck::mission;
using Json = nlohmann::ordered_json;
const std::string kUnknownWall = SWARMCHECK_SCENARIOS "/examples/unknown-wall.json";

TEST(MissionSensing, ScanPutsTheFirstOccupiedCellOfEachReturningBeamOnTheMap) {
  // 8 x 4 cells of 1 m from (0, 0); column 5 occupied (x in [5, 6]).
  sm::WorldDecl d;
  d.resolution_m = 1;
  d.origin = {0, 0};
  d.rows = std::vector<std::string>{".....#..", ".....#..", ".....#..", ".....#.."};
  d.sensor = sm::SensorDecl{4, 3.0, 0.0};
  const auto w = sm::build_world(d);
  // From (2.5, 1.5): east hits x = 5 at t = 2.5 (a multiple of res / 8); north and south reach
  // the border within 3 m (outside the grid counts as a return: cells outside are not marked);
  // west reaches x = 0 at 2.5 (outside: no cell).
  const auto cells = sm::scan_cells(w, {2.5, 1.5}, 1, 0, 0);
  ASSERT_EQ(cells.size(), 1u);
  EXPECT_EQ(cells[0], *sm::cell_of(w, {5.5, 1.5}));
  // From (1.5, 1.5) the wall is 3.5 m away: no return, nothing marked.
  EXPECT_TRUE(sm::scan_cells(w, {1.5, 1.5}, 1, 0, 0).empty());
  std::vector<char> map(w.occupied.size(), 0);
  EXPECT_TRUE(sm::add_to_map(map, cells));
  EXPECT_FALSE(sm::add_to_map(map, cells));
}

TEST(MissionSensing, NoiseIsAStandardNormalKeyedBySeedStepRobotAndBeam) {
  EXPECT_EQ(sm::sensor_normal(7, 3, 1, 2), sm::sensor_normal(7, 3, 1, 2));
  EXPECT_NE(sm::sensor_normal(7, 3, 1, 2), sm::sensor_normal(8, 3, 1, 2));
  EXPECT_NE(sm::sensor_normal(7, 3, 1, 2), sm::sensor_normal(7, 4, 1, 2));
  EXPECT_NE(sm::sensor_normal(7, 3, 1, 2), sm::sensor_normal(7, 3, 0, 2));
  EXPECT_NE(sm::sensor_normal(7, 3, 1, 2), sm::sensor_normal(7, 3, 1, 3));
  double sum = 0, sum2 = 0;
  const int n = 20000;
  for (int k = 0; k < n; ++k) {
    const double g = sm::sensor_normal(1, static_cast<std::uint64_t>(k), 0, 0);
    sum += g;
    sum2 += g * g;
  }
  EXPECT_NEAR(sum / n, 0.0, 0.03);
  EXPECT_NEAR(sum2 / n, 1.0, 0.05);
}

std::string message_for(const swarmcheck::test::EditJson& edit) {
  return swarmcheck::test::message_of_edited("sensing", kUnknownWall,
                                             SWARMCHECK_SCENARIOS "/examples/two-tasks.fsm", edit);
}

TEST(MissionSensing, BadSensorsAndUnknownObstaclesGetOneMessageAtTheirJsonPath) {
  EXPECT_EQ(message_for([](Json&) {}), "");
  EXPECT_EQ(message_for([](Json& j) { j["world"]["sensor"]["beams"] = 0; }),
            "world.sensor.beams: expected 1 to 4096 beams; got 0");
  // Each at its bound passes; together over a big world they are tens of millions of samples a scan.
  EXPECT_EQ(message_for([](Json& j) {
              j["world"]["sensor"] = {{"beams", 4096}, {"range_m", 1000}, {"noise_m", 0.02}};
              j["world"]["size_m"] = {250, 250};
            }),
            "world.sensor: 4096 beams reaching 353.6 m in cells of 0.25 m take 4.63e+07 samples a scan (each robot, "
            "each step); at most 4.19e+06: fewer beams, a shorter range or larger cells");
  EXPECT_EQ(message_for([](Json& j) { j["world"]["sensor"] = {{"beams", 4096}, {"range_m", 1000}, {"noise_m", 0.02}}; }), "");
  EXPECT_EQ(message_for([](Json& j) { j["world"]["sensor"]["range_m"] = -1; }),
            "world.sensor.range_m: expected a range in metres, > 0 and at most 1000; got -1");
  EXPECT_EQ(message_for([](Json& j) { j["world"]["sensor"]["noise_m"] = 4; }),
            "world.sensor.noise_m: expected a standard deviation in metres, >= 0 and at most the "
            "range; got 4");
  EXPECT_EQ(message_for([](Json& j) { j["world"]["sensor"].erase("noise_m"); }),
            "world.sensor.noise_m: missing (the readings' standard deviation in metres)");
  EXPECT_EQ(message_for([](Json& j) { j["world"]["unknown_obstacles"][0]["polygon"] = {{1, 1}, {2, 2}}; }),
            "world.unknown_obstacles[0].polygon: expected a polygon of at least 3 points [x, y]; got 2");
  EXPECT_EQ(message_for([](Json& j) {
              j["world"]["unknown_obstacles"][0]["polygon"] = {{7, -1}, {9, -1}, {8, 1}};
            }),
            "tasks[0].at: an unknown obstacle covers task t1 at [8, 0] for robot A (radius 0.25 m)");
  EXPECT_EQ(message_for([](Json& j) {
              j["world"]["unknown_obstacles"][0]["polygon"] = {{-1, -1}, {1, -1}, {0, 1}};
            }),
            "robots[0].start: robot A (radius 0.25 m) at [0, 0] overlaps an unknown obstacle");
}

void unknown_wall_run(sm::BodyModel body) {
  const auto m = sm::load_mission(kUnknownWall);
  ASSERT_FALSE(m.world->hidden.empty());
  const auto run = swarmcheck::test::run_traced(m, body);
  const auto& [o, r, t] = run;
  ASSERT_EQ(swarmcheck::test::unclean(m, run), "");  // never on the unknown wall, nor on B
  EXPECT_EQ(r.makespan_planned, 8.0);  // the plan knows no wall: straight to t1
  EXPECT_GT(r.replans_sensed, 0u);     // A met the wall and re-routed
  EXPECT_EQ(r.bumps, 0u);              // seen in time: never held back by touching it
  EXPECT_GT(r.travel[0], 9.5);         // around it
  sm::RunOptions other = o;  // another seed: other noise, the same outcome
  other.seed = 99;
  const sm::RunResult r2 = sm::run_mission(m, other);
  EXPECT_TRUE(r2.completed) << r2.reason;
  EXPECT_NE(r2.travel[0], r.travel[0]);
  EXPECT_EQ(swarmcheck::conformance::mission::diff_run(m, other).value_or(""), "");
}

TEST(MissionSensing, RobotMeetsAnUnmappedWallReplansAndCompletesWithoutCollisionKinematic) {
  unknown_wall_run(sm::BodyModel::kinematic);
}

TEST(MissionSensing, RobotMeetsAnUnmappedWallReplansAndCompletesWithoutCollisionUnicycle) {
  unknown_wall_run(sm::BodyModel::unicycle);
}

}  // namespace
