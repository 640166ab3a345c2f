// Polygon obstacles (spec/mission/polygon.hpp): the rasterisation rule on hand-made cases and on
// random polygons, the file's checks (one message at the polygon's JSON path), and the polygon
// example run to completion without touching a wall or another robot, library and model alike.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstdlib>
#include <functional>
#include <nlohmann/json.hpp>

#include "conformance/mission/differential.hpp"
#include "spec/mission/polygon.hpp"
#include "spec/mission/world.hpp"
#include "spec/util/input_error.hpp"
#include "swarmcheck/mission.hpp"
#include "tests/mission/edited_mission.hpp"
#include "tests/mission/replay.hpp"

namespace {

namespace sm = swarmcheck::mission;
using Json = nlohmann::ordered_json;
const std::string kPolygons = SWARMCHECK_SCENARIOS "/examples/polygons.json";
const bool kSeededPolygon = [] { return ::setenv("RC_PARAMS", "seed=31 max_success=300", 0) == 0; }();

sm::GridWorld free_grid(double res, sm::Point origin, sm::Point size, std::vector<std::vector<sm::Point>> polys) {
  sm::WorldDecl d;
  d.resolution_m = res;
  d.origin = origin;
  d.size_m = size;
  d.obstacles.emplace();
  for (auto& p : polys) d.obstacles->push_back(sm::ObstacleDecl{std::move(p)});
  return sm::build_world(d);
}

std::string picture(const sm::GridWorld& w) {
  std::string out;
  for (std::size_t i = 0; i < w.rows; ++i) {
    for (std::size_t j = 0; j < w.cols; ++j) out += w.occupied[i * w.cols + j] ? '#' : '.';
    out += '\n';
  }
  return out;
}

TEST(MissionPolygon, ACellIsOccupiedExactlyWhenThePolygonMeetsItsOpenSquare) {
  // 4 x 4 cells of 1 m from (0, 0); row 0 is the top, y in [3, 4].
  // The square [1, 2] x [1, 2] exactly: only its own cell (its edges lie on cell borders).
  EXPECT_EQ(picture(free_grid(1, {0, 0}, {4, 4}, {{{1, 1}, {2, 1}, {2, 2}, {1, 2}}})),
            "....\n....\n.#..\n....\n");
  // A hair larger: the 8 neighbours' open squares are met too.
  EXPECT_EQ(picture(free_grid(1, {0, 0}, {4, 4}, {{{0.99, 0.99}, {2.01, 0.99}, {2.01, 2.01}, {0.99, 2.01}}})),
            "....\n###.\n###.\n###.\n");
  // A thin diagonal sliver occupies every cell it passes through (no gap a robot could cross).
  EXPECT_EQ(picture(free_grid(1, {0, 0}, {4, 4}, {{{0.5, 0.5}, {3.5, 3.4}, {3.5, 3.5}}})),
            "...#\n..##\n.##.\n##..\n");
  // A triangle touching a cell only at a corner leaves it free.
  EXPECT_EQ(picture(free_grid(1, {0, 0}, {4, 4}, {{{2, 2}, {4, 2}, {4, 4}}})),
            "...#\n..##\n....\n....\n");
  // Rasterised onto rows: the union with the '#' cells; size_m rounds up to whole cells.
  sm::WorldDecl d;
  d.resolution_m = 1;
  d.origin = {0, 0};
  d.rows = std::vector<std::string>{"#...", "....", "....", "...."};
  d.obstacles = std::vector<sm::ObstacleDecl>{{{{3.2, 0.2}, {3.8, 0.2}, {3.5, 0.8}}}};
  EXPECT_EQ(picture(sm::build_world(d)), "#...\n....\n....\n...#\n");
  const auto w = free_grid(0.5, {0, 0}, {1.1, 0.9}, {});
  EXPECT_EQ(w.cols, 3u);
  EXPECT_EQ(w.rows, 2u);
}

// Random polygons (3..7 points on a quarter-metre lattice, possibly self-intersecting) on a grid of
// 0.5 m cells: no point strictly inside the polygon (even-odd) lies in a free cell's open square,
// and every occupied cell's open square holds a point of the polygon or of an edge (checked by
// sampling the cell on a fine lattice and its edges' crossings).
RC_GTEST_PROP(MissionPolygon, NoPointInsideAPolygonIsInAFreeCellOnRandomPolygons, ()) {
  const auto n = *rc::gen::inRange<std::size_t>(3, 8);
  std::vector<sm::Point> poly;
  for (std::size_t k = 0; k < n; ++k)
    poly.push_back({*rc::gen::inRange(0, 25) * 0.25, *rc::gen::inRange(0, 25) * 0.25});
  RC_PRE(sm::polygon_area2(poly) != 0.0);
  const auto w = free_grid(0.5, {0, 0}, {6, 6}, {poly});
  for (int a = 0; a < 120; ++a)
    for (int b = 0; b < 120; ++b) {
      // Off every lattice line (cells, vertices): an irrational offset.
      const sm::Point p{a * 0.05 + 0.0123456789 * std::sqrt(2.0), b * 0.05 + 0.0217 * std::sqrt(3.0)};
      if (!sm::inside_polygon(poly, p)) continue;
      const auto c = sm::cell_of(w, p);
      RC_ASSERT(c.has_value());
      RC_ASSERT(w.occupied[*c] != 0);
    }
}

// The polygon example, edited by `edit`: "" or the message after "m.json: ".
std::string polygon_message(const swarmcheck::test::EditJson& edit) {
  return swarmcheck::test::message_of_edited("polygon", kPolygons,
                                             SWARMCHECK_SCENARIOS "/examples/two-tasks.fsm", edit);
}

TEST(MissionPolygon, BadPolygonsGetOneMessageAtTheirJsonPath) {
  EXPECT_EQ(polygon_message([](Json&) {}), "");
  EXPECT_EQ(polygon_message([](Json& j) { j["world"]["obstacles"][1]["polygon"] = {{1, 1}, {2, 2}}; }),
            "world.obstacles[1].polygon: expected a polygon of at least 3 points [x, y]; got 2");
  EXPECT_EQ(polygon_message([](Json& j) { j["world"]["obstacles"][0]["polygon"][2] = {2e9, 0}; }),
            "world.obstacles[0].polygon[2]: expected finite coordinates in metres, each within +-1e9");
  EXPECT_EQ(polygon_message([](Json& j) { j["world"]["obstacles"][2]["polygon"] = {{0, 0}, {1, 1}, {2, 2}}; }),
            "world.obstacles[2].polygon: expected a polygon of non-zero area; its points are on one line");
  EXPECT_EQ(polygon_message([](Json& j) { j["world"]["obstacles"][2]["polygon"] = {{2, -5}, {4, -3}, {4, -5}, {2, -3}}; }),
            "world.obstacles[2].polygon: expected a polygon of non-zero area; its outline crosses itself so that "
            "its parts cancel out (list the corners in order around it)");   // a bow-tie
  EXPECT_EQ(polygon_message([](Json& j) { j["world"]["obstacles"][2]["polygon"] = {{-1, -1}, {1, -1}, {0, 0.2}}; }),
            "world.obstacles[2].polygon: the polygon's cells cover the start [0, 0] of robot A "
            "(radius 0.3 m), robots[0].start");
  EXPECT_EQ(polygon_message([](Json& j) { j["world"]["obstacles"][1]["polygon"] = {{7, -1}, {9, -1}, {8, 1}}; }),
            "world.obstacles[1].polygon: the polygon's cells cover task t1 at [8, 0] (tasks[0].at) "
            "for robot A (radius 0.3 m)");
  EXPECT_EQ(polygon_message([](Json& j) {  // a ring around t2's region, the task outside it
              j["world"]["obstacles"][2]["polygon"] = {{2, 2}, {6, 2}, {6, 6}, {2, 6}, {2, 2},
                                                       {3, 3}, {3, 5}, {5, 5}, {5, 3}, {3, 3}};
              j["tasks"][1]["at"] = {0.5, 4};
            }),
            "regions[1]: region reg2 is unreachable for robot B (radius 0.3 m) from its start "
            "[4, -4]: no cell of the region is clear of the walls by its radius plus half a cell "
            "and connected to the start");
  EXPECT_EQ(polygon_message([](Json& j) { j["world"]["obstacles"][0] = {{"polygon", {{4, 1}, {5, 1}, {5, 2}}}, {"hole", 1}}; }),
            "world.obstacles[0].hole: unknown key (expected one of: polygon)");
  EXPECT_EQ(polygon_message([](Json& j) { j["world"]["obstacles"][0].erase("polygon"); }),
            "world.obstacles[0].polygon: missing (its corners in order [[x, y], ...])");
  EXPECT_EQ(polygon_message([](Json& j) { j["world"]["rows"] = {"...."}; }),
            "world.size_m: expected either \"rows\" or \"size_m\", not both");
  EXPECT_EQ(polygon_message([](Json& j) { j["world"]["size_m"] = {0, 3}; }),
            "world.size_m: expected [width, height] in metres, both > 0, of at most 1048576 cells "
            "of 0.25 m; got [0, 3]");
}

void polygons_run(sm::BodyModel body) {
  const auto m = sm::load_mission(kPolygons);
  ASSERT_EQ(m.world->polygons.size(), 3u);
  const auto run = swarmcheck::test::run_traced(m, body);
  ASSERT_EQ(swarmcheck::test::unclean(m, run), "");  // no robot on a wall or another robot
  EXPECT_GE(run.result.clearance_min_m, 0.0);
  for (std::size_t k = 0; k < m.robots.size(); ++k)  // around the diamond: longer than straight
    EXPECT_GT(run.result.travel[k], 8.2) << m.robots[k].name;
}

TEST(MissionPolygon, PolygonMissionCompletesWithoutCollisionAndModelAgreesKinematic) {
  polygons_run(sm::BodyModel::kinematic);
}

TEST(MissionPolygon, PolygonMissionCompletesWithoutCollisionAndModelAgreesUnicycle) {
  polygons_run(sm::BodyModel::unicycle);
}

}  // namespace
