// The optimised library against the reference model, directly: whole runs of the default
// scenario in every rule set and mode (threads_test.cpp: the parallel stages against one thread).
#include <gtest/gtest.h>

#include "model/exploration/exploration_model.hpp"
#include "swarmcheck/exploration.hpp"
#include "tests/conformance/record_difference.hpp"

using namespace swarmcheck;
using namespace swarmcheck::exploration;
using swarmcheck::exploration::testing::first_difference_text;

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

TEST(Impl, InvalidScenarioIsRefusedWithAnInputError) {
  Scenario s = default_scenario();
  s.robots.push_back({0.7, 0.2});   // the same cell as robot 0
  EXPECT_THROW(Exploration x(s), InputError);
}

// A window too big for the deposit kernel's table (more than 2^16 cells: s_range 130) takes the
// row-by-row deposit's fallback path, which no generated case reaches (maps of at most 64).
TEST(Impl, AWindowTooBigToTableDepositsAsTheModelDoes) {
  Scenario s = default_scenario();
  s.map_size = 300;
  s.mode = Mode::abstract;
  s.rule = RuleSet::stochastic;
  s.obstacles.clear();
  s.robots = {{10.5, 10.5}, {150.5, 150.5}, {290.5, 20.5}};
  s.params.s_range = 130;
  swarmcheck::model::exploration::ExplorationModel m(s);
  Exploration x(s);
  for (int k = 0; k < 3; ++k) {
    m.step();
    x.step();
    ASSERT_EQ(first_difference_text(m.record(), x.record()), "") << "step " << k + 1;
  }
}
