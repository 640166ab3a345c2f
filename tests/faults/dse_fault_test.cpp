// The fault catalogue for the DSE library: this file is compiled once per fault of
// tests/faults/dse/, linked with the variant of the library that carries it. The resume property's
// campaign (tests/dse/resume_campaign.hpp) must catch the fault under the seed it is given
// (SWARMCHECK_FAULT_SEED) with a minimal journal, written where it says, and the same seed must
// give the same counterexample again.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "tests/dse/resume_campaign.hpp"
#include "tests/faults/fault_seed.hpp"

using namespace swarmcheck::testing::dse;
namespace faults = swarmcheck::testing::faults;

TEST(Mutation, TheResumeCampaignCatchesTheInjectedFaultWithAMinimalJournal) {
  const auto out = std::filesystem::temp_directory_path() /
                   (std::string("swarmcheck-fault-") + kFaultName + "-" + std::to_string(::getpid()));
  const ResumeReport r = run_resume_campaign(faults::seed(), kResumeCases, out.string());
  ASSERT_TRUE(r.counterexample.has_value()) << "fault " << kFaultName << " survived " << r.cases_run
                                            << " cases with seed " << faults::seed();
  const auto& cx = *r.counterexample;
  faults::check_expected(cx.difference);
  EXPECT_TRUE(std::filesystem::exists(cx.journal_path));
  const ResumeReport again = run_resume_campaign(faults::seed(), kResumeCases, out.string());
  ASSERT_TRUE(again.counterexample.has_value());
  EXPECT_EQ(again.counterexample->difference, cx.difference);
  EXPECT_EQ(again.cases_run, r.cases_run);
  std::printf("fault %s (seed %llu): caught after %d cases; resume kind; journal shrunk %d times to %d lines; %s\n",
              kFaultName, static_cast<unsigned long long>(faults::seed()), r.cases_run, cx.shrinks, cx.journal_lines,
              cx.difference.c_str());
  std::filesystem::remove_all(out);
}
