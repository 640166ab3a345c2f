// pheromone-bounds on concrete runs: random deposits and evaporation steps through the spec's
// functions (deposit_amount, decay_factor, thesis_evaporate) never leave
// [0, R (max_ph + epsilon / a2) / (1 - f)].
#include <cstdlib>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "proofs/obligations/runner.hpp"
#include "spec/exploration/decay.hpp"
#include "spec/exploration/neighbourhood.hpp"

namespace swarmcheck::proofs {
namespace {

// One seed for every run (an RC_PARAMS in the environment wins): CI and a developer see the
// same cases.
const bool kSeededProofsPheromoneTest = [] { return ::setenv("RC_PARAMS", "seed=17", 0) == 0; }();

using exploration::Params;

RC_GTEST_PROP(PheromoneProof, RandomDepositsAndEvaporationStayWithinTheBound, ()) {
  Params p{};
  p.s_range = *rc::gen::inRange<int32_t>(1, 4);
  p.a1 = *rc::gen::element(0.5, 1e-3, 2.0, 1e3);
  p.a2 = *rc::gen::element(0.5, 1e-3, 3.0);
  p.epsilon = *rc::gen::element(0.5, 0.0, 1.0);
  p.max_ph = *rc::gen::element(2.0, 0.0, 10.0);
  p.ertu = *rc::gen::element(0.1, 1.0, 20.0, 0.01);
  p.step_size = *rc::gen::element(0.1, 0.05);
  const bool thesis = *rc::gen::arbitrary<bool>();
  const int robots = *rc::gen::inRange(1, 9);
  const double f = exploration::evaporation_factor(p);
  RC_PRE(f < 1.0);
  const exploration::DecayTable table = exploration::make_decay_table(f);
  const double bound = robots * (p.max_ph + p.epsilon / p.a2) / (1 - f);
  // Double rounding may push tau a few ulps above the real bound; the proof is over reals.
  const double slack = bound * 1e-12;
  double tau = 0;
  const int steps = *rc::gen::inRange(1, 400);
  for (int t = 0; t < steps; ++t) {
    tau = thesis ? exploration::thesis_evaporate(tau, p.ertu * p.step_size)
                 : tau * exploration::decay_factor(table, 1);
    if (*rc::gen::arbitrary<bool>()) {   // a planning step: each robot covering the cell deposits
      for (int r = 0; r < robots; ++r)
        if (*rc::gen::arbitrary<bool>()) {
          const int32_t di = *rc::gen::inRange(-p.s_range, p.s_range + 1);
          const int32_t dj = *rc::gen::inRange(-p.s_range, p.s_range + 1);
          tau = tau + exploration::deposit_amount(p, di, dj);
        }
    }
    RC_ASSERT(tau >= 0.0);
    RC_ASSERT(tau <= bound + slack);
  }
}

TEST(PheromoneProof, Z3ProvesTheBoundForEveryNumberOfRobotsAndEveryAgeOfAValue) {
  const ObligationReport r = run_in_process(*find_obligation("pheromone-bounds"), kQueryTimeoutMs);
  EXPECT_EQ(r.result, Verdict::proved) << r.detail;
  for (const QueryRecord& q : r.queries) EXPECT_EQ(q.answer, "unsat") << q.label;
  // Every part ran: the loops' inductions, the deposit pass at each window size, consecution,
  // and whole steps from environment_stages.
  for (const char* part : {"decay-table", "decay-factor", "deposit-amounts", "deposit-pass-s3", "step-decay",
                           "step-thesis", "whole-step"}) {
    bool found = false;
    for (const QueryRecord& q : r.queries) found = found || q.label.rfind(part, 0) == 0;
    EXPECT_TRUE(found) << part;
  }
  EXPECT_TRUE(r.unread.empty());
}

}  // namespace
}  // namespace swarmcheck::proofs
