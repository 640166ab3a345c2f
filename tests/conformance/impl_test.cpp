// The optimised library against the reference model, directly: whole runs of the default
// scenario in every rule set and mode, and the parallel group planning against one thread.
#include <gtest/gtest.h>

#include "model/exploration/exploration_model.hpp"
#include "spec/util/hana_diff.hpp"
#include "swarmcheck/exploration.hpp"

using namespace swarmcheck;
using namespace swarmcheck::exploration;

namespace {
std::string first_difference_text(const StepRecord& a, const StepRecord& b) {
  const auto d = json_io::first_difference(a, b);
  return d ? d->path + " " + d->a + " vs " + d->b : "";
}
}  // namespace

TEST(Impl, WholeDefaultRunsEqualTheModelInEveryRuleSetAndMode) {
  for (RuleSet rule : {RuleSet::thesis, RuleSet::deterministic, RuleSet::stochastic})
    for (Mode mode : {Mode::abstract, Mode::cosim}) {
      Scenario s = default_scenario();
      s.rule = rule;
      s.mode = mode;
      swarmcheck::model::exploration::ExplorationModel m(s);
      Exploration x(s);
      while (!m.done()) {
        m.step();
        x.step();
        if (m.steps() % 97 == 0) {
          ASSERT_EQ(first_difference_text(m.record(), x.record()), "") << m.steps();
        }
      }
      EXPECT_TRUE(x.done());
      EXPECT_EQ(first_difference_text(m.record(), x.record()), "");
      EXPECT_EQ(x.completion_step(), m.completion_step());
    }
}

TEST(Impl, ParallelGroupPlanningGivesExactlyTheSequentialResultWithThousandsOfRobots) {
  Scenario s = default_scenario();
  s.map_size = 96;
  s.obstacles.clear();
  s.robots.clear();
  for (int32_t i = 0; i < 96; i += 2)
    for (int32_t j = 0; j < 96; j += 3) s.robots.push_back({i + 0.5, j + 0.5});   // 1536 robots
  s.mode = Mode::abstract;
  s.rule = RuleSet::stochastic;
  s.max_steps = 40;
  ExplorationOptions parallel;
  parallel.parallel_min_robots = 1;
  ExplorationOptions sequential;
  sequential.parallel_min_robots = 1 << 30;
  Exploration a(s, parallel), b(s, sequential);
  swarmcheck::model::exploration::ExplorationModel m(s);
  while (!m.done()) {
    a.step();
    b.step();
    m.step();
    ASSERT_EQ(first_difference_text(a.record(), b.record()), "") << a.steps();
  }
  EXPECT_EQ(first_difference_text(m.record(), a.record()), "");
}

TEST(Impl, InvalidScenarioIsRefusedWithAnInputError) {
  Scenario s = default_scenario();
  s.robots.push_back({0.7, 0.2});   // the same cell as robot 0
  EXPECT_THROW(Exploration x(s), InputError);
}
