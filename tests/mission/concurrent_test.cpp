// Concurrent execution (spec/mission/run.hpp rule 1): robots work at once on the plan's events,
// the plan is kept unless a strictly better one appears, and the run is a word of the
// supervisor. Properties on generated obstacle-free allocation missions with the kinematic body
// (conformance/mission/generate_concurrent.cpp), seeded so the cases are the same every time.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <cstdlib>

#include "conformance/mission/generate.hpp"
#include "model/mission/run_model.hpp"
#include "spec/mission/avoidance.hpp"
#include "spec/mission/plan.hpp"
#include "swarmcheck/mission.hpp"

namespace {

namespace sm = swarmcheck::mission;
namespace cm = swarmcheck::conformance::mission;

const bool kSeededConcurrent = [] { return ::setenv("RC_PARAMS", "seed=14 max_success=150", 0) == 0; }();

std::vector<std::string> names(const std::vector<sm::EventRecord>& events, bool controllable_only) {
  std::vector<std::string> out;
  for (const auto& e : events)
    if (!controllable_only || e.controllable) out.push_back(e.event);
  return out;
}

std::vector<std::string> first_plan(const sm::Mission& m) {
  const sm::Plan p = sm::Planner(m).plan(sm::initial_query(m));
  RC_ASSERT(p.found);
  return p.events;
}

RC_GTEST_PROP(MissionConcurrent, ExecutedAssignmentEqualsTheFirstPlansOnGeneratedMissions, ()) {
  const cm::RunCase c = *cm::concurrent_case();
  const sm::RunResult r = sm::run_mission(c.mission, c.options);
  RC_ASSERT(r.completed);
  RC_TAG(r.replans > 1 ? "replanned" : "one plan");
  RC_ASSERT(sm::task_sequences(c.mission, names(r.events, true)) ==
            sm::task_sequences(c.mission, first_plan(c.mission)));
}

// Every event fired where the supervisor enabled it, in the state the record names, and the
// run ends at a marked state: on the concurrent cases and on the differential's run cases
// (random supervisors and regions, both bodies), up to where those runs end.
void check_word(const sm::Mission& m, const sm::RunResult& r) {
  std::string q = m.initial_state;
  for (const auto& e : r.events) {
    const auto next = swarmcheck::supervisor::successor(m.fsm, q, e.event);
    RC_ASSERT(next.has_value());
    RC_ASSERT(*next == e.state_after);
    q = *next;
  }
  RC_ASSERT(q == r.final_state);
  RC_ASSERT(sm::is_marked(m, q) == r.completed);
}

RC_GTEST_PROP(MissionConcurrent, EveryExecutedEventSequenceIsAWordOfTheSupervisor, ()) {
  const cm::RunCase c = *rc::gen::oneOf(cm::concurrent_case(), cm::run_case());
  check_word(c.mission, sm::run_mission(c.mission, c.options));
}

RC_GTEST_PROP(MissionConcurrent, RealisedMakespanIsNeverWorseThanThePlanRobotByRobot, ()) {
  const cm::RunCase c = *cm::concurrent_case();
  const sm::RunResult r = sm::run_mission(c.mission, c.options);
  const sm::RunResult one_by_one = sm::run_mission(cm::robot_by_robot(c.mission, first_plan(c.mission)), c.options);
  RC_ASSERT(r.completed);
  RC_ASSERT(one_by_one.completed);
  RC_TAG(c.mission.robots.size() > 1 && r.time_s < one_by_one.time_s ? "faster" : "as fast");
  RC_ASSERT(r.time_s <= one_by_one.time_s);
}

// The re-interleaving rule 1b falls back on: from the plan's start, a path with the plan's own
// assignment exists, is no longer than the plan, and costs exactly what the plan costs.
RC_GTEST_PROP(MissionConcurrent, PathWithThePlansAssignmentCostsWhatThePlanCosts, ()) {
  const sm::Mission m = *rc::gen::oneOf(cm::random_small_mission(), cm::small_allocation_mission());
  const sm::PlanQuery q = sm::initial_query(m);
  const sm::Plan p = sm::Planner(m).plan(q);
  RC_PRE(p.found);
  const auto tasks = sm::task_sequences(m, p.events);
  const auto path = sm::path_with_assignment(m, q.from, tasks);
  RC_ASSERT(path.has_value());
  RC_ASSERT(path->size() <= p.events.size());
  RC_ASSERT(sm::task_sequences(m, *path) == tasks);
  const sm::PathEvaluation ev = sm::evaluate_path(m, q, *path);
  RC_ASSERT(ev.error.empty());
  RC_ASSERT(ev.cost == p.cost);
}

// The intervals tile each robot's time: from 0 to the end, back to back, activities alternating.
RC_GTEST_PROP(MissionConcurrent, ActivityIntervalsTileEachRobotsTime, ()) {
  const cm::RunCase c = *rc::gen::oneOf(cm::concurrent_case(), cm::run_case());
  const sm::RunResult r = sm::run_mission(c.mission, c.options);
  for (const auto& robot : c.mission.robots) {
    std::vector<sm::IntervalRecord> mine;
    for (const auto& i : r.intervals)
      if (i.robot == robot.name) mine.push_back(i);
    if (r.time_s == 0.0) {
      RC_ASSERT(mine.empty());
      continue;
    }
    RC_ASSERT(!mine.empty());
    RC_ASSERT(mine.front().from_s == 0.0);
    RC_ASSERT(mine.back().to_s == r.time_s);
    for (std::size_t k = 0; k < mine.size(); ++k) {
      RC_ASSERT(mine[k].from_s < mine[k].to_s);
      if (k > 0) RC_ASSERT(mine[k].from_s == mine[k - 1].to_s);
      if (k > 0) RC_ASSERT(mine[k].activity != mine[k - 1].activity);
    }
  }
}

// Rule 1b's robot order: one robot, tasks t0 (5, 0) and t1 (5, 5), a gate region across its way
// to t0. The supervisor allows t1's start right after t0's (q1), before or after the gate's
// entry; the plan enters the gate first (t0, gate, t1). The start of t1 must wait for the gate's
// entry, the robot's own earlier event in the plan, though the supervisor would allow it now.
TEST(MissionConcurrent, ARobotsNextStartWaitsForItsOwnEarlierPlannedEvents) {
  namespace sv = swarmcheck::supervisor;
  sm::MissionDecl d;
  d.fsm = "gate.fsm";
  d.initial_state = "q0";
  d.marked_states = {"q3"};
  d.robots = {sm::RobotDecl{"A", {0, 0}}};
  d.tasks = {sm::TaskDecl{"t0", {5, 0}}, sm::TaskDecl{"t1", {5, 5}}};
  d.regions = {sm::RegionDecl{"gate", {sm::Point{1, -1}, sm::Point{3, 1}}}};
  d.events = {{"a_s0", {"A", "t0", std::nullopt}}, {"a_s1", {"A", "t1", std::nullopt}},
              {"a_e_gate", {"A", std::nullopt, "gate"}}};
  sv::Automaton fsm;
  fsm.states = {"q0", "q1", "q2", "q3", "q4"};
  fsm.marked = {"q3"};
  fsm.events = {{"a_s0", {true, true}}, {"a_s1", {true, true}}, {"a_e_gate", {false, true}}};
  fsm.delta["q0"]["a_s0"] = "q1";
  fsm.delta["q1"]["a_e_gate"] = "q2";
  fsm.delta["q2"]["a_s1"] = "q3";
  fsm.delta["q1"]["a_s1"] = "q4";
  fsm.delta["q4"]["a_e_gate"] = "q3";
  const sm::Mission m = sm::check_mission(d, fsm, "gate.json");
  ASSERT_EQ(sm::Planner(m).plan(sm::initial_query(m)).events,
            (std::vector<std::string>{"a_s0", "a_e_gate", "a_s1"}));
  sm::RunOptions o;
  o.body = sm::BodyModel::kinematic;
  const sm::RunResult r = sm::run_mission(m, o);
  ASSERT_TRUE(r.completed) << r.reason;
  ASSERT_EQ(names(r.events, false), (std::vector<std::string>{"a_s0", "a_e_gate", "a_s1"}));
  EXPECT_GT(r.events[1].time_s, 0.0);
  EXPECT_EQ(r.events[2].time_s, r.events[1].time_s);  // issued the moment the gate was entered
}

// Rule 1a on the reference model, whose planner is a parameter: after the first plan (A: t1,
// B: t2, C: t3 on the three-robot mission), every replan offers A: t1, t2 instead (B idle),
// claiming a cost equal to the plan in hand, or 1 m less. Equal keeps the plan; strictly better replaces it.
// (With the exact planner a kept plan is never beaten: its cost is the first plan's, bit for bit.)
std::vector<std::vector<std::size_t>> executed_with_rival(double claimed_gain) {
  const sm::Mission m = sm::load_mission(SWARMCHECK_SCENARIOS "/examples/three-robots.json");
  sm::Planner exact(m);
  bool first = true;
  const swarmcheck::model::mission::PlanFunction rival = [&](const sm::PlanQuery& q) {
    sm::Plan p = exact.plan(q);
    if (first || !p.found) {
      first = false;
      return p;
    }
    auto tasks = sm::task_sequences(m, p.events);
    if (tasks[1].empty()) return p;  // B already started: nothing to hand over
    tasks[0].insert(tasks[0].end(), tasks[1].begin(), tasks[1].end());
    tasks[1].clear();
    const auto other = sm::path_with_assignment(m, q.from, tasks);
    if (!other) return p;
    p.events = *other;
    p.cost.makespan -= claimed_gain;
    return p;
  };
  sm::RunOptions o;
  o.body = sm::BodyModel::kinematic;
  const sm::RunResult r = swarmcheck::model::mission::run_model(m, o, rival);
  EXPECT_TRUE(r.completed) << r.reason;
  return sm::task_sequences(m, names(r.events, true));
}

TEST(MissionConcurrent, ReplanKeepsThePlanAgainstAnEquallyGoodRival) {
  EXPECT_EQ(executed_with_rival(0.0), (std::vector<std::vector<std::size_t>>{{0}, {1}, {2}}));
}

TEST(MissionConcurrent, ReplanTakesAStrictlyBetterRival) {
  EXPECT_EQ(executed_with_rival(1.0), (std::vector<std::vector<std::size_t>>{{0, 1}, {}, {2}}));
}

}  // namespace
