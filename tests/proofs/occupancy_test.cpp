// occupancy on concrete runs: random model steps of the fixed rule sets keep every robot in
// the map, off obstacles and alone in its cell; and the spec's choose_rule interpreted in Z3
// picks the cell the executed choose() picks.
#include <cstdlib>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "model/exploration/exploration_model.hpp"
#include "proofs/obligations/occupancy.hpp"
#include "proofs/obligations/runner.hpp"
#include "spec/exploration/choice.hpp"
#include "spec/exploration/invariants.hpp"
#include "tests/exploration/scenario_gen.hpp"

namespace swarmcheck::proofs {
namespace {

// One seed for every run (an RC_PARAMS in the environment wins): CI and a developer see the
// same cases.
const bool kSeededProofsOccupancyTest = [] { return ::setenv("RC_PARAMS", "seed=17", 0) == 0; }();

using namespace exploration;

RC_GTEST_PROP(OccupancyProof, RandomModelStepsOfTheFixedRuleSetsKeepRobotsApartAndOffObstacles, ()) {
  Scenario s = *testing::gen_scenario(8, 30, 200);
  s.rule = *rc::gen::element(RuleSet::deterministic, RuleSet::stochastic);
  swarmcheck::model::exploration::ExplorationModel m(s);
  while (!m.done()) {
    m.step();
    const StepRecord r = m.record();
    RC_ASSERT(check_occupancy(s, r.robots).empty());
  }
}

// The two interpretations of choose_rule agree: interpreted in Z3 over a window with absent
// cells and evaluated at the window's values, it picks the cell the executed choose() picks on
// the window's present cells.
RC_GTEST_PROP(OccupancyProof, SymbolicChoiceInZ3IsTheExecutedChoiceOnThePresentCells, ()) {
  const auto set = *rc::gen::element(RuleSet::deterministic, RuleSet::thesis);
  const int s_range = *rc::gen::inRange(1, 3);
  const auto cands = occupancy::symbolic_window(s_range, "w");
  const std::size_t n = cands.size();
  const auto present = *rc::gen::container<std::vector<bool>>(n, rc::gen::arbitrary<bool>());
  // Ties; the thesis rule divides by the sum of the keys, which the real theory cannot do at 0
  // (IEEE gives inf and NaN there), so its pheromone is positive.
  const int lowest = set == RuleSet::thesis ? 1 : 0;
  const auto tau = *rc::gen::container<std::vector<int>>(n, rc::gen::inRange(lowest, lowest + 3));
  const auto blocked = *rc::gen::container<std::vector<bool>>(n, rc::gen::arbitrary<bool>());
  Params p{};
  p.phi = 1.0;
  p.lambda = 1.0;
  p.eta = 1.0;
  const ChoiceTerms terms = choice_terms(p);
  std::vector<Candidate> spec_cands;
  std::vector<int> slot_of;   // spec index -> slot
  z3::context c;
  Translator t(c, RealTheory::real, false, 8);
  const occupancy::ChoiceQuery q = occupancy::choice_query(t, rules_of(set), cands);
  z3::expr_vector from(c), to(c);
  from.push_back(c.real_const("eta_term"));
  to.push_back(c.real_val(std::to_string(terms.eta_term).c_str()));
  from.push_back(c.real_const("thesis_best_start"));
  to.push_back(c.real_val(std::to_string(static_cast<int>(terms.thesis_best_start)).c_str()));
  for (std::size_t k = 0; k < n; ++k) {
    from.push_back(t(cands[k].present));
    to.push_back(c.bool_val(present[k]));
    from.push_back(t(cands[k].tau));
    to.push_back(c.real_val(tau[k]));
    from.push_back(t(cands[k].blocked));
    to.push_back(c.bool_val(blocked[k]));
    if (!present[k]) continue;
    spec_cands.push_back(Candidate{CellIndex{0, static_cast<int32_t>(k)}, static_cast<double>(tau[k]), blocked[k]});
    slot_of.push_back(static_cast<int>(k));
  }
  RC_PRE(terms.thesis_best_start == 1000.0);
  const Choice ch = choose(rules_of(set), terms, spec_cands, DrawSite{0, 0, 0});
  const int expected = ch.target < 0 ? -1 : slot_of[static_cast<std::size_t>(ch.target)];
  // The window's values fix the target: it is the executed choice, and nothing else.
  z3::solver solver(c);
  solver.add(t.side_conditions());
  for (unsigned k = 0; k < from.size(); ++k) solver.add(from[static_cast<int>(k)] == to[static_cast<int>(k)]);
  const z3::expr want = c.bv_val(expected, 8);
  RC_ASSERT(solver.check() == z3::sat);
  RC_ASSERT(solver.get_model().eval(q.target, true).get_numeral_uint() == want.get_numeral_uint());
  solver.add(q.target != want);
  RC_ASSERT(solver.check() == z3::unsat);
}

TEST(OccupancyProof, Z3ProvesOnePlanningStepKeepsOccupancy) {
  const ObligationReport r = run_in_process(*find_obligation("occupancy"), kQueryTimeoutMs);
  EXPECT_EQ(r.result, Verdict::proved) << r.detail;
  for (const QueryRecord& q : r.queries) EXPECT_EQ(q.answer, "unsat") << q.label;
}

}  // namespace
}  // namespace swarmcheck::proofs
