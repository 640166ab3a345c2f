// The runner's watchdog: a prover that never answers is killed at its deadline and reported
// unknown, and one that crashes is reported unknown, so `prove` never hangs or dies with it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>

#include "proofs/obligations/runner.hpp"

namespace swarmcheck::proofs {
namespace {

TEST(ProofRunner, AProverThatNeverAnswersIsKilledAtTheDeadlineAndReportedUnknown) {
  const Obligation hangs{"hangs", "never answers", Verdict::proved, {"none"}, [](Session&) -> Outcome {
                           for (;;) ::pause();
                         }, {}};
  const ObligationReport r = run_isolated(hangs, 0.5, 1000);
  EXPECT_EQ(r.result, Verdict::unknown);
  EXPECT_NE(r.detail.find("watchdog"), std::string::npos) << r.detail;
  EXPECT_LT(r.seconds, 5.0);
  EXPECT_FALSE(r.met());
}

TEST(ProofRunner, AProverThatCrashesIsReportedUnknown) {
  const Obligation crashes{"crashes", "aborts", Verdict::proved, {"none"}, [](Session&) -> Outcome {
                             std::raise(SIGKILL);
                             return {};
                           }, {}};
  const ObligationReport r = run_isolated(crashes, 5, 1000);
  EXPECT_EQ(r.result, Verdict::unknown);
  EXPECT_NE(r.detail.find("signal"), std::string::npos) << r.detail;
}

TEST(ProofRunner, TheChildsReportComesBackWhole) {
  const ObligationReport r = run_isolated(*find_obligation("handshake-late-controller"), 30, kQueryTimeoutMs);
  EXPECT_EQ(r.result, Verdict::refuted) << r.detail;
  ASSERT_TRUE(r.trace.has_value());
  EXPECT_EQ(r.trace->file_name, "handshake-late-controller.jsonl");
  EXPECT_FALSE(r.queries.empty());
  for (const QueryRecord& q : r.queries) EXPECT_NE(q.smt2.find("(check-sat)"), std::string::npos);
}

}  // namespace
}  // namespace swarmcheck::proofs
