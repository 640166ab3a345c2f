// The resume property (tests/dse/resume_campaign.hpp) with the default seed and budget: a sweep
// resumed from a journal of missing points, cut lines, repeated points (the last line wins) and
// lines in any order gives the uninterrupted sweep's results, computing only what is missing.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "tests/dse/resume_campaign.hpp"

using namespace swarmcheck::testing::dse;

TEST(DseResume, AnyJournalOfMissingCutRepeatedAndReorderedLinesGivesTheUninterruptedResults) {
  const auto out = std::filesystem::temp_directory_path() / ("swarmcheck-resume-test-" + std::to_string(::getpid()));
  const ResumeReport r = run_resume_campaign(1, kResumeCases, out.string());
  ASSERT_FALSE(r.counterexample.has_value()) << r.counterexample->difference << "\n  journal: "
                                             << r.counterexample->journal_path;
  EXPECT_EQ(r.cases_run, kResumeCases);
  // What the cases reached: points read back, points with older lines before their last, cut lines.
  EXPECT_GT(r.points_resumed, kResumeCases);
  EXPECT_GT(r.repeated_points, kResumeCases / 2);
  EXPECT_GT(r.cut_lines, kResumeCases / 4);
  std::filesystem::remove_all(out);
}
