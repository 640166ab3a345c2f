// The fault catalogue for the automata library: this file is compiled once per fault of
// tests/faults/supervisor/, linked with the variant of the library that carries it. The default
// automata campaign must catch the fault under the seed it is given (SWARMCHECK_FAULT_SEED) with a
// minimal counterexample: its inputs written as .fsm files that read back, the difference (a
// crash of the library included) reproduced by the minimal inputs alone, in a child process.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "conformance/supervisor/campaign.hpp"
#include "swarmcheck/supervisor.hpp"
#include "tests/faults/fault_seed.hpp"

using namespace swarmcheck::conformance::supervisor;
namespace faults = swarmcheck::testing::faults;

TEST(Mutation, TheAutomataCampaignCatchesTheInjectedFaultWithAMinimalCounterexample) {
  CampaignOptions o;   // the default budget, as `swarmcheck conform --system automata --seed S`
  o.seed = swarmcheck::conformance::derive_seed(faults::seed(), "automata");
  o.quiet_limit = faults::quiet_limit();
  o.out_dir = (std::filesystem::temp_directory_path() /
               (std::string("swarmcheck-fault-") + kFaultName + "-" + std::to_string(::getpid())))
                  .string();
  const CampaignReport r = run_campaign(o);
  ASSERT_TRUE(r.counterexample.has_value()) << "fault " << kFaultName << " survived " << r.cases_run
                                            << " cases with seed " << faults::seed();
  const Counterexample& cx = *r.counterexample;
  faults::check_expected(cx.difference);
  ASSERT_EQ(cx.files.size(), cx.inputs.size());
  for (std::size_t i = 0; i < cx.files.size(); ++i)
    EXPECT_EQ(swarmcheck::supervisor::read_fsm_file(cx.files[i]), cx.inputs[i]) << cx.files[i];
  EXPECT_EQ(diff_case_isolated(cx.kind, cx.inputs, o.quiet_limit).value_or("(agree)"), cx.difference);
  std::printf("fault %s (seed %llu): caught after %d cases; %s kind; %s case shrunk %d times (%d tried) to %zu states in "
              "all; %s\n",
              kFaultName, static_cast<unsigned long long>(faults::seed()), r.cases_run, cx.caught_by.c_str(),
              cx.kind.c_str(), cx.shrinks, cx.shrink_tries, cx.states,
              cx.difference.substr(0, cx.difference.find('\n')).c_str());
  std::filesystem::remove_all(o.out_dir);
}
