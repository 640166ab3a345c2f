// The fault catalogue for the automata library: this file is compiled once per fault of
// tests/faults/supervisor/, linked with the variant of the library that carries it. The default
// automata campaign must catch the fault with a minimal counterexample: its inputs written as
// .fsm files that read back, the difference reproduced by the minimal inputs alone.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "conformance/supervisor/campaign.hpp"
#include "swarmcheck/supervisor.hpp"

// The fault this executable carries: one generated line per fault (tests/faults/CMakeLists.txt),
// so this file is compiled once per subsystem and linked with every variant.
extern const char* const kFaultName;

using namespace swarmcheck::conformance::supervisor;

TEST(Mutation, TheAutomataCampaignCatchesTheInjectedFaultWithAMinimalCounterexample) {
  CampaignOptions o;   // the default budget and seed, as `swarmcheck conform --system automata`
  o.seed = swarmcheck::conformance::derive_seed(1, "automata");
  o.out_dir = (std::filesystem::temp_directory_path() /
               (std::string("swarmcheck-fault-") + kFaultName + "-" + std::to_string(::getpid())))
                  .string();
  const CampaignReport r = run_campaign(o);
  ASSERT_TRUE(r.counterexample.has_value()) << "fault " << kFaultName << " survived " << r.cases_run << " cases";
  const Counterexample& cx = *r.counterexample;
  ASSERT_EQ(cx.files.size(), cx.inputs.size());
  for (std::size_t i = 0; i < cx.files.size(); ++i)
    EXPECT_EQ(swarmcheck::supervisor::read_fsm_file(cx.files[i]), cx.inputs[i]) << cx.files[i];
  EXPECT_EQ(diff_case(cx.kind, cx.inputs).value_or("(agree)"), cx.difference);   // reproduces by itself
  std::printf("fault %s: caught after %d cases; %s case shrunk %d times (%d tried) to %zu states in all; %s\n",
              kFaultName, r.cases_run, cx.kind.c_str(), cx.shrinks, cx.shrink_tries, cx.states,
              cx.difference.substr(0, cx.difference.find('\n')).c_str());
  std::filesystem::remove_all(o.out_dir);
}
