// The proof-mutation check: this file is compiled once and linked with every variant of the
// spec that carries one fault of tests/proofs/faults/ (the proofs' objects read the variant's
// rules, as the executed code does). The obligation the fault breaks must come back refuted,
// so `prove` exits 1, with a counterexample confirmed by replaying it through the executed
// (faulty) code: not unknown, not a model the code does not reproduce.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "proofs/obligations/runner.hpp"

extern const char* const kFaultName;
extern const char* const kFaultObligation;

TEST(ProofMutation, TheBrokenObligationIsRefutedWithACounterexampleTheExecutedCodeReplays) {
  using namespace swarmcheck::proofs;
  const Obligation* o = find_obligation(kFaultObligation);
  ASSERT_NE(o, nullptr) << "fault " << kFaultName << " names no obligation " << kFaultObligation;
  ASSERT_EQ(o->expected, Verdict::proved) << "a fault must break an obligation that holds";
  const ObligationReport r = run_isolated(*o, kObligationTimeoutS, kQueryTimeoutMs);
  EXPECT_EQ(r.result, Verdict::refuted) << "fault " << kFaultName << ": " << r.detail;
  EXPECT_FALSE(r.met()) << "prove would still exit 0";
  EXPECT_NE(r.detail.find("confirmed"), std::string::npos) << r.detail;
  EXPECT_EQ(r.detail.find("NOT reproduced"), std::string::npos) << r.detail;
  std::printf("fault %s: %s %s in %.2f s: %s\n", kFaultName, kFaultObligation, to_string(r.result), r.seconds,
              r.detail.c_str());
  // The proof for every number of robots reads the same rules: it must not still say proved.
  if (std::string(kFaultObligation) == "handshake-safety") {
    const ObligationReport any = run_isolated(*find_obligation("handshake-safety-any-robots"), kObligationTimeoutS, kQueryTimeoutMs);
    EXPECT_NE(any.result, Verdict::proved) << "the counter abstraction misses fault " << kFaultName;
    std::printf("fault %s: handshake-safety-any-robots %s: %s\n", kFaultName, to_string(any.result), any.detail.c_str());
  }
}
