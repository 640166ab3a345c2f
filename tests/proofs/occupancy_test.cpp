// occupancy on concrete runs: random model steps of the fixed rule sets keep every robot in
// the map, off obstacles and alone in its cell; and the proof's symbolic deterministic choice
// picks the cell the spec's deterministic choice picks.
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

RC_GTEST_PROP(OccupancyProof, SymbolicDeterministicChoiceIsTheSpecsChoice, ()) {
  // A 3 x 3 window: 8 candidate slots in raster order, some out of the map.
  const auto valid = *rc::gen::container<std::vector<bool>>(8, rc::gen::arbitrary<bool>());
  const auto tau = *rc::gen::container<std::vector<int>>(8, rc::gen::inRange(0, 3));   // ties
  const auto blocked = *rc::gen::container<std::vector<bool>>(8, rc::gen::arbitrary<bool>());
  Params p{};
  p.phi = 1.0;
  p.lambda = 1.0;
  p.eta = 1.0;
  std::vector<Candidate> spec_cands;
  std::vector<int> slot_of;   // spec index -> slot
  z3::context c;
  std::vector<occupancy::SymCandidate> sym;
  for (int k = 0; k < 8; ++k) {
    const auto u = static_cast<std::size_t>(k);
    sym.push_back({c.bool_val(valid[u]), c.real_val(tau[u]), c.bool_val(blocked[u])});
    if (!valid[u]) continue;
    spec_cands.push_back(Candidate{CellIndex{k / 3, k % 3}, static_cast<double>(tau[u]), blocked[u]});
    slot_of.push_back(k);
  }
  const Choice ch = choose(rules_of(RuleSet::deterministic), choice_terms(p), spec_cands, DrawSite{0, 0, 0});
  const int expected = ch.target < 0 ? -1 : slot_of[static_cast<std::size_t>(ch.target)];
  const z3::expr got = occupancy::deterministic_target(c, sym).simplify();
  RC_ASSERT(got.get_numeral_int() == expected);
}

TEST(OccupancyProof, Z3ProvesOnePlanningStepKeepsOccupancy) {
  const ObligationReport r = run_in_process(*find_obligation("occupancy"), 20000);
  EXPECT_EQ(r.result, Verdict::proved) << r.detail;
  for (const QueryRecord& q : r.queries) EXPECT_EQ(q.answer, "unsat") << q.label;
}

}  // namespace
}  // namespace swarmcheck::proofs
