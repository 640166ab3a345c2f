// Robots never overlap each other (spec/mission/separation.hpp, spec/mission/run.hpp rule 3): the
// yield rule's test, the starts' check, the crossing example (one robot yields, both finish), a
// head-on deadlock in a narrow corridor with its reason, and the property on generated missions with radii: at no step
// are two robots closer than the sum of their radii, and the library equals the model bit for bit.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstdlib>
#include <functional>
#include <nlohmann/json.hpp>

#include "conformance/mission/differential.hpp"
#include "conformance/mission/generate.hpp"
#include "spec/mission/separation.hpp"
#include "spec/util/hana_json.hpp"
#include "spec/util/input_error.hpp"
#include "swarmcheck/mission.hpp"
#include "tests/mission/edited_mission.hpp"
#include "tests/mission/replay.hpp"

namespace {

namespace sm = swarmcheck::mission;
namespace cm = swarmcheck::conformance::mission;
using Json = nlohmann::ordered_json;
const std::string kCrossing = SWARMCHECK_SCENARIOS "/examples/crossing.json";
const bool kSeededSeparation = [] { return ::setenv("RC_PARAMS", "seed=23 max_success=400", 0) == 0; }();

// The crossing example edited by `edit` (or the InputError's text after "m.json: " in `error`).
std::optional<sm::Mission> crossing_with(const swarmcheck::test::EditJson& edit, std::string* error) {
  return swarmcheck::test::load_edited("separation", kCrossing,
                                       SWARMCHECK_SCENARIOS "/examples/two-tasks.fsm", edit, error);
}

TEST(MissionSeparation, YieldsToTheFirstOverlappingRobotAndTouchingIsAllowed) {
  sm::Mission m;
  m.robots = {{"A", {0, 0}, 0.5}, {"B", {3, 0}, 0.5}, {"C", {0, 3}, 1.0}, {"D", {9, 9}, 0.0}};
  const std::vector<sm::Point> at{{0, 0}, {3, 0}, {0, 3}, {9, 9}};
  const auto still_at = [](const sm::Point& p) { return sm::RobotWay{p, false, {}, std::nullopt}; };
  const std::vector<sm::RobotWay> still{still_at(at[0]), still_at(at[1]), still_at(at[2]), still_at(at[3])};
  EXPECT_FALSE(sm::yields_to(m, 0, at[0], {2, 0}, still).has_value());  // touching B only
  EXPECT_EQ(sm::yields_to(m, 0, at[0], {2.01, 0}, still), std::size_t{1});
  EXPECT_EQ(sm::yields_to(m, 1, at[1], {0.2, 0.9}, still), std::size_t{0});
  EXPECT_FALSE(sm::yields_to(m, 3, at[3], {9, 9}, still).has_value());  // itself is no obstacle
  EXPECT_EQ(sm::yields_to(m, 3, at[3], {3, 0.4}, still), std::size_t{1});  // inside B's disk
  EXPECT_EQ(sm::clearance_m(m, at), 1.5);  // A and C: 3 - 1.5
  // A's way from (0, 0) to (6, 0): B (later) may not come within 1 + 0.25 m of it, nor closer
  // than it was; moving away, or along at the same distance, is free. A never yields to a way.
  std::vector<sm::RobotWay> ways = still;
  ways[0] = {at[0], true, {6, 0}, std::nullopt};
  ways[1] = {{3, -2}, true, {3, 2}, std::nullopt};
  EXPECT_FALSE(sm::yields_to(m, 1, {3, -2}, {3, -1.3}, ways).has_value());
  EXPECT_EQ(sm::yields_to(m, 1, {3, -1.3}, {3, -1.2}, ways), std::size_t{0});
  EXPECT_FALSE(sm::yields_to(m, 1, {3, -1.2}, {3, -1.3}, ways).has_value());
  EXPECT_FALSE(sm::yields_to(m, 1, {3, -1.2}, {3.1, -1.2}, ways).has_value());
  EXPECT_FALSE(sm::yields_to(m, 0, at[0], {0.1, 0}, ways).has_value());
  ways[0].yielded_to = 1;  // A waits for B: B clears A's way instead of keeping off it
  EXPECT_FALSE(sm::yields_to(m, 1, {3, -1.3}, {3, -1.2}, ways).has_value());
  ways[0].yielded_to = 2;
  EXPECT_EQ(sm::yields_to(m, 1, {3, -1.3}, {3, -1.2}, ways), std::size_t{0});
  EXPECT_DOUBLE_EQ(sm::distance_to_segment({7, 1}, {0, 0}, {6, 0}), std::sqrt(2.0));
  EXPECT_EQ(sm::distance_to_segment({3, 4}, {0, 0}, {0, 0}), 5.0);
  // Point robots keep no distance from ways.
  m.robots[1].radius = 0.0;
  m.robots[0].radius = 0.0;
  EXPECT_FALSE(sm::yields_to(m, 1, {3, -1.3}, {3, -0.1}, ways).has_value());
  sm::Mission one;
  one.robots = {{"A", {0, 0}, 0.5}};
  EXPECT_EQ(sm::clearance_m(one, std::vector<sm::Point>{{0, 0}}), sm::kNoClearance);
}

TEST(MissionSeparation, StartsCloserThanTheirRadiiAreRefusedAtTheirJsonPath) {
  std::string error;
  EXPECT_TRUE(crossing_with([](Json&) {}, &error).has_value());
  EXPECT_TRUE(crossing_with([](Json& j) { j["robots"][1]["start"] = {1, 0}; }, &error).has_value());
  EXPECT_FALSE(crossing_with([](Json& j) { j["robots"][1]["start"] = {0.9, 0.1}; }, &error).has_value());
  EXPECT_EQ(error, "robots[1].start: robot B (radius 0.5 m) at [0.9, 0.1] overlaps robot A (radius "
                   "0.5 m) at [0, 0]: starts must be at least the sum of the radii apart");
}

void crossing_run(sm::BodyModel body) {
  const auto m = sm::load_mission(kCrossing);
  const auto run = swarmcheck::test::run_traced(m, body);
  const auto& [o, r, t] = run;
  ASSERT_EQ(swarmcheck::test::unclean(m, run), "");  // no overlap at any step, events enabled
  EXPECT_GT(r.yields, 0u);
  EXPECT_GE(r.clearance_min_m, 0.0);
  EXPECT_LT(r.clearance_min_m, 0.5);  // they did come close
  std::size_t yielded_steps = 0;
  for (const auto& e : t.entries)
    if (!e.is_event && e.step.yielded[1]) ++yielded_steps;
  EXPECT_EQ(yielded_steps, r.yields);  // only B, the later in index order, yields
  bool b_waited = false;
  for (const auto& i : r.intervals)
    b_waited = b_waited || (i.robot == "B" && i.activity == sm::Activity::waiting_for_robot);
  EXPECT_TRUE(b_waited);
}

TEST(MissionSeparation, CrossingRobotsYieldAndCompleteWithoutOverlapKinematic) {
  crossing_run(sm::BodyModel::kinematic);
}

TEST(MissionSeparation, CrossingRobotsYieldAndCompleteWithoutOverlapUnicycle) {
  crossing_run(sm::BodyModel::unicycle);
}

// A head-on meeting in a corridor too narrow to pass (1.5 m; robots of radius 0.25 m may end
// their detours only on cells traversable for them, the middle row): each would overlap the
// other, B finds no way aside (spec/mission/steering.hpp), and the run ends in a deadlock that
// names who waits for whom. (In the open, B steers aside: tests/mission/steering_test.cpp.)
TEST(MissionSeparation, HeadOnRobotsInATooNarrowCorridorDeadlockWithAReasonNamingWhoYieldsToWhom) {
  const auto m = crossing_with([](Json& j) {
    j["robots"][1]["start"] = {8, 0};
    j["tasks"][1]["at"] = {0, 0};
    j["regions"][1]["corners"] = {{-0.5, -0.5}, {0.5, 0.5}};
    for (auto& r : j["robots"]) r["radius"] = 0.25;
    const std::string wall(22, '#'), free(22, '.');
    j["world"] = {{"resolution_m", 0.5}, {"origin", {-1, -1.25}}, {"rows", {wall, free, free, free, wall}}};
  }, nullptr);
  ASSERT_TRUE(m.has_value());
  sm::RunOptions o;
  o.body = sm::BodyModel::kinematic;
  const sm::RunResult r = sm::run_mission(*m, o);
  EXPECT_FALSE(r.completed);
  EXPECT_EQ(r.reason, "deadlock in state sww: no robot can move (enabled events: a1f, b2f); "
                      "robot A yields to robot B; robot B yields to robot A");
  EXPECT_EQ(r.steers, 0u);
  EXPECT_GT(r.travel[0] + r.travel[1], 7.4);  // they met half way, 0.5 m apart
  EXPECT_LE(r.travel[0] + r.travel[1], 7.5);
  EXPECT_GE(r.clearance_min_m, 0.0);
  EXPECT_EQ(cm::diff_run(*m, o).value_or(""), "");
}

// Crowded allocation missions: 2..4 robots and 1..3 tasks on half-metre points of [-4, 4]^2 (starts
// outside the tasks' 2 m squares), so that robots' ways cross and meet; either body.
rc::Gen<cm::RunCase> crowded_case() {
  return rc::gen::exec([] {
    const auto robots = *rc::gen::inRange<std::size_t>(2, 5);
    const auto tasks = *rc::gen::inRange<std::size_t>(2, 4);
    const auto point = [] { return sm::Point{*rc::gen::inRange(-8, 9) * 0.5, *rc::gen::inRange(-8, 9) * 0.5}; };
    std::vector<sm::Point> starts, points;
    for (std::size_t r = 0; r < robots; ++r) starts.push_back(point());
    for (std::size_t t = 0; t < tasks; ++t) points.push_back(point());
    cm::RunCase c{cm::allocation_mission_at(starts, points), {}};
    for (const auto& s : starts)
      for (const auto& g : c.mission.regions) RC_PRE(!sm::inside(g, s));
    c.options.body = *rc::gen::element(sm::BodyModel::kinematic, sm::BodyModel::unicycle);
    c.options.dt_s = *rc::gen::element(0.05, 0.1, 0.2);
    c.options.max_time_s = 300;
    return c;
  });
}

struct Steps : sm::RunObserver {
  std::vector<sm::StepRecord> steps;
  void on_event(const sm::EventRecord&) override {}
  void on_step(const sm::StepRecord& s) override { steps.push_back(s); }
};

// Generated missions (the differential's run cases, the concurrent allocation cases and crowded
// allocation cases, either body) with radii of 0.2..0.6 m; cases whose starts overlap are discarded. Every step record has
// every pair at least r_a + r_b apart, the result's clearance is that least gap, and the model
// gives the same result and records, bit for bit.
RC_GTEST_PROP(MissionSeparation,
              NoTwoRobotsCloserThanTheSumOfRadiiAtAnyStepAndImplEqualsModelOnGeneratedMissions, ()) {
  cm::RunCase c = *rc::gen::oneOf(cm::run_case(), cm::concurrent_case(), crowded_case(), crowded_case());
  for (auto& robot : c.mission.robots) robot.radius = *rc::gen::element(0.2, 0.4, 0.6);
  try {
    sm::check_robots_apart(c.mission);
  } catch (const swarmcheck::InputError&) {
    RC_DISCARD("the starts overlap");
  }
  Steps seen;
  const sm::RunResult r = sm::run_mission(c.mission, c.options, &seen);
  double least = sm::kNoClearance;
  for (const auto& s : seen.steps) {
    for (std::size_t a = 0; a < s.positions.size(); ++a)
      for (std::size_t b = 0; b < a; ++b)
        RC_ASSERT(sm::distance(s.positions[a], s.positions[b]) >=
                  c.mission.robots[a].radius + c.mission.robots[b].radius);
    least = std::min(least, sm::clearance_m(c.mission, s.positions));
  }
  RC_ASSERT(r.clearance_min_m == least);  // a deadlocked step (unrecorded) moves no one
  RC_TAG(r.yields > 0 ? "a robot yielded" : "no yield", r.completed ? "complete" : r.reason.substr(0, 8));
  const auto d = cm::diff_run(c.mission, c.options);
  RC_ASSERT(d.value_or("") == std::string());
}

}  // namespace
