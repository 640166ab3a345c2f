// The fault catalogue for the mission library: this file is compiled once per fault of
// tests/faults/mission/, linked with the variant of the library that carries it. The default
// mission campaign must catch the fault with a minimal counterexample, written as a mission file
// (with its .fsm) that loads, and the same seed must give the same counterexample again.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "conformance/mission/campaign.hpp"
#include "swarmcheck/mission.hpp"

// The fault this executable carries: one generated line per fault (tests/faults/CMakeLists.txt),
// so this file is compiled once per subsystem and linked with every variant.
extern const char* const kFaultName;

using namespace swarmcheck::conformance::mission;

TEST(Mutation, TheMissionCampaignCatchesTheInjectedFaultWithAMinimalCounterexample) {
  CampaignOptions o;   // the default budget and seed, as `swarmcheck conform --system missions`
  o.seed = swarmcheck::conformance::derive_seed(1, "missions");
  o.out_dir = (std::filesystem::temp_directory_path() /
               (std::string("swarmcheck-fault-") + kFaultName + "-" + std::to_string(::getpid())))
                  .string();
  const CampaignReport r = run_campaign(o);
  ASSERT_TRUE(r.counterexample.has_value()) << "fault " << kFaultName << " survived " << r.cases_run << " cases";
  const auto& cx = *r.counterexample;
  const swarmcheck::mission::Mission m = swarmcheck::mission::load_mission(cx.mission_path);   // it loads
  EXPECT_EQ(m.fsm.states.size(), cx.fsm_states);
  const CampaignReport again = run_campaign(o);   // reproducible: same seed, same counterexample
  ASSERT_TRUE(again.counterexample.has_value());
  EXPECT_EQ(again.counterexample->difference, cx.difference);
  EXPECT_EQ(again.cases_run, r.cases_run);
  std::printf("fault %s: caught after %d cases; %s case shrunk %d times to %zu robots, %zu tasks, %zu FSM states; %s\n",
              kFaultName, r.cases_run, cx.kind.c_str(), cx.shrinks, cx.robots, cx.tasks, cx.fsm_states,
              cx.difference.c_str());
  std::filesystem::remove_all(o.out_dir);
}
