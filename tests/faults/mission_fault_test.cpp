// The fault catalogue for the mission library: this file is compiled once per fault of
// tests/faults/mission/, linked with the variant of the library that carries it. The default
// mission campaign must catch the fault under the seed it is given (SWARMCHECK_FAULT_SEED) with a
// minimal counterexample, written as a mission file (with its .fsm, and its world) that loads
// and, for a run, shows the same difference again; and the same seed must give the same
// counterexample again.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "conformance/mission/campaign.hpp"
#include "swarmcheck/mission.hpp"
#include "tests/faults/fault_seed.hpp"

using namespace swarmcheck::conformance::mission;
namespace faults = swarmcheck::testing::faults;

TEST(Mutation, TheMissionCampaignCatchesTheInjectedFaultWithAMinimalCounterexample) {
  CampaignOptions o;   // the default budget, as `swarmcheck conform --system missions --seed S`
  o.seed = swarmcheck::conformance::derive_seed(faults::seed(), "missions");
  o.quiet_limit = faults::quiet_limit();
  o.out_dir = (std::filesystem::temp_directory_path() /
               (std::string("swarmcheck-fault-") + kFaultName + "-" + std::to_string(::getpid())))
                  .string();
  const CampaignReport r = run_campaign(o);
  ASSERT_TRUE(r.counterexample.has_value()) << "fault " << kFaultName << " survived " << r.cases_run
                                            << " cases with seed " << faults::seed();
  const auto& cx = *r.counterexample;
  faults::check_expected(cx.difference);
  const swarmcheck::mission::Mission m = swarmcheck::mission::load_mission(cx.mission_path);   // it loads
  EXPECT_EQ(m.fsm.states.size(), cx.fsm_states);
  if (cx.run_options) {   // the files hold the whole case: the mission as loaded shows the difference again
    EXPECT_EQ(diff_run_isolated(m, *cx.run_options, o.quiet_limit).value_or("(agree)"), cx.difference);
  }
  if (!faults::expects("hang")) {   // (a hang costs the time limit for each case that hangs)
    const CampaignReport again = run_campaign(o);   // reproducible: same seed, same counterexample
    ASSERT_TRUE(again.counterexample.has_value());
    EXPECT_EQ(again.counterexample->difference, cx.difference);
    EXPECT_EQ(again.cases_run, r.cases_run);
  }
  std::printf("fault %s (seed %llu): caught after %d cases; %s kind; %s case shrunk %d times to %zu robots, %zu tasks, "
              "%zu FSM states; %s\n",
              kFaultName, static_cast<unsigned long long>(faults::seed()), r.cases_run, cx.caught_by.c_str(),
              cx.kind.c_str(), cx.shrinks, cx.robots, cx.tasks, cx.fsm_states, cx.difference.c_str());
  std::filesystem::remove_all(o.out_dir);
}
