// "Reads what runs": an obligation's reads (the spec functions its queries interpreted) must
// include every spec function its property passes through in the executed step (read off the
// step's symbolic interpretation from its entry point). The step paths name what the step calls;
// an obligation that skips one (here, a planted one that states evaporation as the old encoding
// did, one multiplication by the evaporation factor) is not met, so `prove` exits 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "proofs/obligations/runner.hpp"
#include "proofs/obligations/translate.hpp"
#include "spec/exploration/decay.hpp"
#include "spec/exploration/deposit.hpp"

namespace swarmcheck::proofs {
namespace {

bool contains(const std::vector<std::string>& v, const std::string& x) { return std::find(v.begin(), v.end(), x) != v.end(); }

std::vector<std::string> step_calls(const char* obligation) {
  const Obligation* o = find_obligation(obligation);
  EXPECT_NE(o, nullptr) << obligation;
  if (!o || !o->step) return {};
  return sym::called_functions(o->step());
}

void expect_calls(const char* obligation, std::initializer_list<const char*> functions) {
  const std::vector<std::string> calls = step_calls(obligation);
  for (const char* f : functions) EXPECT_TRUE(contains(calls, f)) << obligation << " does not pass through " << f;
}

TEST(ReadsWhatRuns, TheStepsPathsNameTheFunctionsTheExecutedStepCalls) {
  expect_calls("pheromone-bounds",
               {"exploration::decay_factor", "exploration::make_decay_table", "exploration::evaporation_factor_rule",
                "exploration::decayed_pheromone_rule", "exploration::thesis_evaporate_rule", "exploration::deposit_around",
                "exploration::deposit_amount_rule", "exploration::deposited_pheromone_rule", "exploration::window_around",
                "exploration::gather_candidates", "exploration::choose_rule", "exploration::decide"});
  expect_calls("occupancy", {"exploration::window_around", "exploration::gather_candidates", "exploration::choose_rule",
                             "exploration::decide", "exploration::apply_decision_to_grid",
                             "exploration::apply_decision_to_robot"});
  expect_calls("handshake-safety", {"exploration::master_step", "exploration::all_arrived_rule",
                                    "exploration::handshake_stage", "exploration::environment_handshake_rule",
                                    "exploration::controller_rule"});
  expect_calls("handshake-safety-any-robots", {"exploration::master_step", "exploration::all_arrived_rule",
                                               "exploration::handshake_stage", "exploration::controller_rule"});
  expect_calls("handshake-epoch-gauss-seidel", {"exploration::master_step", "exploration::epoch_environment_rule",
                                                "exploration::epoch_controller_rule", "exploration::arrived_rule"});
  expect_calls("handshake-epoch-late-any-robots", {"exploration::master_step", "exploration::epoch_environment_rule",
                                                   "exploration::epoch_controller_rule"});
  expect_calls("servo-controller-range", {"exploration::controller_rule"});
  expect_calls("all-arrived-any-robots", {"exploration::master_step", "exploration::all_arrived_rule"});
}

// The pheromone bound as the encoding before this check stated it: the next value of a cell is
// the evaporation factor times its value plus a deposit, never the decay table, the decay
// function or the deposit stage the step runs.
Outcome planted_pheromone(Session& session) {
  using S = num::Symbolic;
  Translator t(session, RealTheory::real);
  const sym::Real tau = sym::Real::var("tau"), ertu = sym::Real::var("ertu"), dt = sym::Real::var("step_size");
  const sym::Real next =
      exploration::evaporation_factor_rule<S>(ertu, dt) * tau +
      exploration::deposit_amount_rule<S>({sym::Real::var("max_ph"), sym::Real::var("a1"), sym::Real::var("epsilon"),
                                           sym::Real::var("a2")},
                                          sym::Real(0.0));
  z3::solver s = session.make_solver();
  s.add(t(next) != t(next));
  return {session.check(s, "planted") == z3::unsat ? Verdict::proved : Verdict::unknown, "planted", {}};
}

TEST(ReadsWhatRuns, APlantedObligationThatSkipsTheDecayFunctionIsNotMet) {
  const Obligation planted{"planted-pheromone", "the pheromone bound, planted", Verdict::proved, {"planted"},
                           planted_pheromone, find_obligation("pheromone-bounds")->step};
  const ObligationReport r = run_in_process(planted, kQueryTimeoutMs);
  EXPECT_EQ(r.result, Verdict::proved) << r.detail;
  EXPECT_FALSE(r.met()) << "an obligation that restates the step is met";
  EXPECT_TRUE(contains(r.reads, "exploration::evaporation_factor_rule"));
  for (const char* skipped : {"exploration::decay_factor", "exploration::make_decay_table", "exploration::deposit_around",
                              "exploration::window_around"})
    EXPECT_TRUE(contains(r.unread, skipped)) << skipped;
  EXPECT_FALSE(contains(r.unread, "exploration::evaporation_factor_rule"));
}

TEST(ReadsWhatRuns, UnreadStepCallsAreTheStepCallsMissingFromTheReadsInStepOrder) {
  EXPECT_EQ(unread_step_calls({"a", "b", "c"}, {"c", "a"}), std::vector<std::string>{"b"});
  EXPECT_TRUE(unread_step_calls({"a"}, {"a", "z"}).empty());
  EXPECT_TRUE(unread_step_calls({}, {}).empty());
}

}  // namespace
}  // namespace swarmcheck::proofs
