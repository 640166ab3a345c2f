// Planner properties on random missions over random supervisors, and the thesis mission.
#include <cstdlib>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "conformance/mission/differential.hpp"
#include "conformance/mission/generate.hpp"
#include "impl/mission/planner.hpp"
#include "model/mission/thesis_dijkstra.hpp"
#include "swarmcheck/mission.hpp"

namespace {

// One seed for every run (an RC_PARAMS in the environment wins): CI and a developer see the
// same cases.
const bool kSeededMissionPlannerTest = [] { return ::setenv("RC_PARAMS", "seed=17", 0) == 0; }();

namespace sm = swarmcheck::mission;
using swarmcheck::impl::mission::Planner;
const std::string kMission = SWARMCHECK_SCENARIOS "/thesis/thesis-mission.json";

RC_GTEST_PROP(MissionPlanner, ExactPlanIsNeverWorseThanTheThesisBaseline, ()) {
  const auto m = *swarmcheck::conformance::mission::random_small_mission();
  Planner planner(m);
  const auto q = sm::initial_query(m);
  const auto exact = planner.plan(q);
  const auto base = swarmcheck::model::mission::thesis_plan(m, q);
  RC_CLASSIFY(exact.found, "a marked state is reachable");
  RC_ASSERT(exact.found == base.found);
  if (exact.found) RC_ASSERT(!sm::better(base.cost, exact.cost));
}

// The differential runner (conformance/mission/differential): exact vs brute force, cost bit for
// bit, and the exact plan is a path with the cost it states.
RC_GTEST_PROP(MissionPlanner, ExactPlanCostEqualsBruteForceOnSmallInstances, ()) {
  const auto m = *swarmcheck::conformance::mission::random_small_mission();
  if (const auto d = swarmcheck::conformance::mission::diff_plan(m, sm::initial_query(m)))
    RC_FAIL(*d);
}

RC_GTEST_PROP(MissionPlanner, EveryPlanIsAnFsmPathEndingInAMarkedStateWithItsStatedCost, ()) {
  const auto m = *swarmcheck::conformance::mission::random_small_mission();
  Planner planner(m);
  const auto q = sm::initial_query(m);
  for (const auto& p : {planner.plan(q), swarmcheck::model::mission::thesis_plan(m, q)}) {
    if (!p.found) continue;
    const auto ev = sm::evaluate_path(m, q, p.events);
    RC_ASSERT(ev.error.empty());
    RC_ASSERT(ev.final_state == p.final_state);
    RC_ASSERT(ev.cost == p.cost);
  }
}

RC_GTEST_PROP(MissionPlanner, ReplanningFromAnyStateWithMovedRobotsIsExactAndCached, ()) {
  const auto m = *swarmcheck::conformance::mission::random_small_mission();
  Planner planner(m);
  sm::PlanQuery q = sm::initial_query(m);
  q.from = *rc::gen::elementOf(m.fsm.states);
  for (auto& p : q.positions) p = {double(*rc::gen::inRange(-5, 6)), double(*rc::gen::inRange(-5, 6))};
  for (auto& t : q.travel) t = double(*rc::gen::inRange(0, 20));
  std::optional<std::string> d;
  try {
    d = swarmcheck::conformance::mission::diff_plan(m, q);
  } catch (const std::length_error&) {  // brute force's walk budget: too big for the oracle
    RC_DISCARD("beyond the brute-force oracle");
  }
  if (d) RC_FAIL(*d);
  const auto exact = planner.plan(q);
  const auto hits = planner.cache_hits();
  const auto again = planner.plan(q);
  RC_ASSERT(planner.cache_hits() == hits + 1);
  RC_ASSERT(again.events == exact.events);
}

std::vector<std::string> task_names(const sm::Mission& m, const std::vector<std::size_t>& ts) {
  std::vector<std::string> out;
  for (const auto t : ts) out.push_back(m.tasks[t].name);
  return out;
}

TEST(MissionPlanner, ThesisMissionExactPlanIsTheThesisAnswer) {
  const auto m = sm::load_mission(kMission);
  Planner planner(m);
  const auto p = planner.plan(sm::initial_query(m));
  ASSERT_TRUE(p.found);
  const auto seq = sm::task_sequences(m, p.events);
  EXPECT_EQ(task_names(m, seq[0]), (std::vector<std::string>{"tsk3", "tsk4"}));
  EXPECT_EQ(task_names(m, seq[1]), (std::vector<std::string>{"tsk1", "tsk2"}));
  // B: |(9,-19)-(-2,-5)| + |(-2,-5)-(7,8)| = sqrt(317) + sqrt(250); the thesis's 33.6 m.
  EXPECT_DOUBLE_EQ(p.cost.makespan, std::sqrt(317.0) + std::sqrt(250.0));
  EXPECT_EQ(p.final_state, "s134:146:143");
}

// The public Planner keeps its own copy of the mission: it outlives the value it was given and
// moves, and plans as the library's planner does.
TEST(MissionPlanner, PublicPlannerOwnsItsMissionAndPlansAsTheLibrary) {
  auto m = std::make_unique<sm::Mission>(sm::load_mission(kMission));
  Planner internal(*m);
  const auto expected = internal.plan(sm::initial_query(*m));
  const sm::PlanQuery q = sm::initial_query(*m);
  sm::Planner moved(*m);
  m.reset();
  sm::Planner planner = std::move(moved);
  const auto p = planner.plan(q);
  EXPECT_EQ(p.events, expected.events);
  EXPECT_EQ(p.cost, expected.cost);
  EXPECT_EQ(planner.plan(q).events, p.events);
  EXPECT_EQ(planner.cache_hits(), 1u);
}

TEST(MissionPlanner, ThesisBaselineFindsTheSameAssignmentOnTheThesisMission) {
  const auto m = sm::load_mission(kMission);
  const auto p = swarmcheck::model::mission::thesis_plan(m, sm::initial_query(m));
  ASSERT_TRUE(p.found);
  const auto seq = sm::task_sequences(m, p.events);
  EXPECT_EQ(task_names(m, seq[0]), (std::vector<std::string>{"tsk3", "tsk4"}));
  EXPECT_EQ(task_names(m, seq[1]), (std::vector<std::string>{"tsk1", "tsk2"}));
}

TEST(MissionPlanner, ExactBeatsTheBaselineOnAGeneratedAllocationMission) {
  // Found by the docs' comparison: the baseline costs every start from the robots' starts.
  int better = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const auto m = swarmcheck::conformance::mission::allocation_mission(2, 3, seed);
    Planner planner(m);
    const auto q = sm::initial_query(m);
    const auto e = planner.plan(q);
    const auto b = swarmcheck::model::mission::thesis_plan(m, q);
    ASSERT_TRUE(e.found && b.found);
    ASSERT_FALSE(sm::better(b.cost, e.cost));
    better += sm::better(e.cost, b.cost) ? 1 : 0;
  }
  EXPECT_GT(better, 0);
}

}  // namespace
