// Unit tests of the spec's rules: neighbourhood, deposit, decay, choice, RNG.
#include <cstdlib>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <limits>
#include <set>

#include "spec/exploration/choice.hpp"
#include "spec/exploration/decay.hpp"
#include "spec/exploration/neighbourhood.hpp"
#include "spec/exploration/rng.hpp"
#include "spec/exploration/scenario.hpp"

using namespace swarmcheck::exploration;

TEST(Neighbourhood, WindowIsClippedToTheMap) {
  const Window corner = window_around({0, 0}, 1, 10);
  EXPECT_EQ(corner.i_lo, 0);
  EXPECT_EQ(corner.i_hi, 1);
  EXPECT_EQ(corner.j_lo, 0);
  EXPECT_EQ(corner.j_hi, 1);
  const Window inner = window_around({4, 7}, 2, 10);
  EXPECT_EQ(inner.i_lo, 2);
  EXPECT_EQ(inner.i_hi, 6);
  EXPECT_EQ(inner.j_lo, 5);
  EXPECT_EQ(inner.j_hi, 9);
  const Window beyond = window_around({1, 1}, 1000, 3);   // s_range beyond the map
  EXPECT_EQ(beyond.i_lo, 0);
  EXPECT_EQ(beyond.i_hi, 2);
}

// Hand-computed with the thesis's default parameters (a1 = a2 = 0.5, epsilon 0.5, max_ph 2):
// centre 2 e^0 + 1 = 3; orthogonal 2 e^-2 + 1; diagonal 2 e^(-2 sqrt 2) + 1.
TEST(Deposit, ThesisValuesAtCentreOrthogonalAndDiagonal) {
  const Params p = default_params();
  EXPECT_EQ(deposit_amount(p, 0, 0), 3.0);
  EXPECT_EQ(deposit_amount(p, 1, 0), 1.2706705664732254);
  EXPECT_EQ(deposit_amount(p, 0, -1), 1.2706705664732254);
  EXPECT_EQ(deposit_amount(p, 1, 1), 1.1182114931239124);
  EXPECT_EQ(deposit_amount(p, -1, 1), 1.1182114931239124);
}

TEST(Cells, CellOfAndCentreOf) {
  EXPECT_EQ(cell_of({0.5, 9.99}, 1.0), (CellIndex{0, 9}));
  EXPECT_EQ(cell_of({2.0, 3.0}, 0.5), (CellIndex{4, 6}));
  EXPECT_EQ(centre_of({3, 0}, 1.0), (Point_m{3.5, 0.5}));
  EXPECT_EQ(centre_of({3, 0}, 2.0), (Point_m{7.0, 1.0}));
}

TEST(Exploration, PercentOfFreeCells) {
  EXPECT_EQ(exploration_percent(96, 96), 100.0);
  EXPECT_EQ(exploration_percent(48, 96), 50.0);
  EXPECT_EQ(exploration_percent(0, 7), 0.0);
}

TEST(Decay, FactorIsTheProductOfSquaredPowersOverSetBits) {
  const DecayTable t = make_decay_table(0.99);
  EXPECT_EQ(decay_factor(t, 0), 1.0);
  EXPECT_EQ(decay_factor(t, 1), 0.99);
  EXPECT_EQ(decay_factor(t, 2), 0.9801);
  EXPECT_EQ(decay_factor(t, 4), 0.96059601);
  EXPECT_EQ(decay_factor(t, 5), 1.0 * 0.99 * 0.96059601);   // bits 0 and 2, increasing i
}

TEST(Decay, FactorIsClampedAtZeroWhenErtuDtReachesOne) {
  Params p = default_params();
  p.ertu = 20.0;   // ertu * step_size = 2
  EXPECT_EQ(evaporation_factor(p), 0.0);
  const DecayTable t = make_decay_table(0.0);
  EXPECT_EQ(decay_factor(t, 0), 1.0);
  EXPECT_EQ(decay_factor(t, 3), 0.0);
}

TEST(Decay, ThesisEvaporationIsTheLiteralUpdateClampedAtZero) {
  EXPECT_EQ(thesis_evaporate(3.0, 0.01), 3.0 - 0.01 * 3.0);
  EXPECT_EQ(thesis_evaporate(3.0, 2.0), 0.0);   // would be -3
  EXPECT_EQ(thesis_evaporate(0.0, 0.5), 0.0);
}

RC_GTEST_PROP(Decay, FactorStaysInUnitIntervalAndNeverGrowsWithAge, ()) {
  const double f = *rc::gen::map(rc::gen::inRange(0, 1000001), [](int k) { return k / 1e6; });
  const auto k = *rc::gen::inRange<int64_t>(0, int64_t{1} << 40);
  const DecayTable t = make_decay_table(f);
  const double a = decay_factor(t, k);
  RC_ASSERT(a >= 0.0);
  RC_ASSERT(a <= 1.0);
  RC_ASSERT(decay_factor(t, k + 1) <= a);
}

namespace {

// One seed for every run (an RC_PARAMS in the environment wins): CI and a developer see the
// same cases.
const bool kSeededExplorationRulesTest = [] { return ::setenv("RC_PARAMS", "seed=17", 0) == 0; }();
std::vector<Candidate> row(std::initializer_list<std::pair<double, bool>> taus) {
  std::vector<Candidate> c;
  int32_t j = 0;
  for (auto [tau, blocked] : taus) c.push_back(Candidate{{0, j++}, tau, blocked});
  return c;
}

// The choice of a rule set's row, with the seed, tick and robot of the draws.
Choice choose_by(RuleSet rule, const std::vector<Candidate>& c, const Params& p, uint64_t seed = 0,
                 int64_t tick = 0, int32_t robot = 0) {
  return choose(rules_of(rule), choice_terms(p), c, DrawSite{seed, tick, robot});
}
}  // namespace

TEST(Choice, ThesisTakesTheLastOfEqualMinima) {
  const auto c = row({{1.0, false}, {0.5, false}, {2.0, false}, {0.5, false}});
  const Choice ch = choose_by(RuleSet::thesis, c, default_params());
  EXPECT_EQ(ch.best, 3);
  EXPECT_EQ(ch.target, 3);
  EXPECT_FALSE(ch.fallback);
}

TEST(Choice, ThesisBlockedBestFallsBackToTheFirstFreeCell) {
  const auto c = row({{1.0, true}, {3.0, false}, {0.5, true}, {2.0, false}});
  const Choice ch = choose_by(RuleSet::thesis, c, default_params());
  EXPECT_EQ(ch.best, 2);
  EXPECT_EQ(ch.target, 1);
  EXPECT_TRUE(ch.fallback);
}

TEST(Choice, ThesisBlockedBestWithNoFreeCellStays) {
  const auto c = row({{1.0, true}, {0.5, true}});
  const Choice ch = choose_by(RuleSet::thesis, c, default_params());
  EXPECT_EQ(ch.best, 1);
  EXPECT_EQ(ch.target, -1);
}

TEST(Choice, ThesisAllZeroPheromoneTiesEveryCandidate) {
  const auto c = row({{0.0, false}, {0.0, false}, {0.0, false}});
  EXPECT_EQ(choose_by(RuleSet::thesis, c, default_params()).best, 2);
}

TEST(Choice, ThesisIgnoresCellsAboveTheInitialBestOfAThousand) {
  // best starts at 1000^phi eta^lambda / sum: only cells scoring at most that qualify.
  const auto c = row({{500.0, false}, {2000.0, false}});
  EXPECT_EQ(choose_by(RuleSet::thesis, c, default_params()).best, 0);
}

TEST(Choice, DeterministicMatchesTheLastMinimumAndFirstFreeFallback) {
  Params p = default_params();
  EXPECT_EQ(choose_by(RuleSet::deterministic, row({{0.2, false}, {0.2, false}, {0.3, false}}), p).best, 1);
  const Choice ch = choose_by(RuleSet::deterministic, row({{0.9, false}, {0.1, true}, {0.5, false}}), p);
  EXPECT_EQ(ch.best, 1);
  EXPECT_EQ(ch.target, 0);
  EXPECT_EQ(choose_by(RuleSet::deterministic, {}, p).target, -1);
}

TEST(Choice, DeterministicWithNegativePhiPrefersTheStrongestPheromone) {
  Params p = default_params();
  p.phi = -1.0;   // tau^-1: zero pheromone scores +inf
  EXPECT_EQ(choose_by(RuleSet::deterministic, row({{0.0, false}, {4.0, false}, {2.0, false}}), p).best, 1);
}

TEST(Choice, StochasticReachesEveryTiedMinimumAndOnlyThose) {
  const auto c = row({{0.5, false}, {1.0, false}, {0.5, false}, {0.5, false}});
  std::set<int32_t> seen;
  for (uint64_t s = 0; s < 200; ++s) {
    const Choice ch = choose_by(RuleSet::stochastic, c, default_params(), s, 0, 0);
    seen.insert(ch.best);
  }
  EXPECT_EQ(seen, (std::set<int32_t>{0, 2, 3}));
}

TEST(Choice, StochasticFallbackPicksOnlyFreeCells) {
  const auto c = row({{2.0, false}, {0.1, true}, {3.0, true}, {4.0, false}});
  std::set<int32_t> seen;
  for (uint64_t s = 0; s < 200; ++s)
    seen.insert(choose_by(RuleSet::stochastic, c, default_params(), s, 1, 2).target);
  EXPECT_EQ(seen, (std::set<int32_t>{0, 3}));
}

bool same_decision(const RobotDecision& a, const RobotDecision& b) {
  return a.moves == b.moves && a.to == b.to && a.occupies == b.occupies && a.marks == b.marks && a.mark == b.mark &&
         a.deposit_centre == b.deposit_centre;
}

// The shortcut impl takes for a robot with no free cell around it is choose() then decide(), for
// any pheromone (NaN and infinities included), any number of candidates, any draw site.
RC_GTEST_PROP(Choice, AWalledInDecisionIsWhatChooseAndDecideGiveWhenNoCandidateIsFree, ()) {
  const auto rule = *rc::gen::element(RuleSet::thesis, RuleSet::deterministic, RuleSet::stochastic);
  const auto n = *rc::gen::inRange(0, 49);
  std::vector<Candidate> c;
  for (int32_t k = 0; k < n; ++k) {
    const double tau = *rc::gen::oneOf(rc::gen::element(0.0, -0.0, 1.0, std::numeric_limits<double>::infinity(),
                                                        std::numeric_limits<double>::quiet_NaN()),
                                       rc::gen::map(rc::gen::inRange(0, 1000000), [](int v) { return v / 1000.0; }));
    c.push_back(Candidate{{k / 7, k % 7}, tau, true});
  }
  Params p = default_params();
  p.phi = *rc::gen::element(1.0, 0.0, 2.0, -1.0, 0.5);
  const CellIndex current{*rc::gen::inRange(0, 100), *rc::gen::inRange(0, 100)};
  const auto shortcut = walled_in_decision(rules_of(rule), current);
  RC_ASSERT(shortcut.has_value() == (rules_of(rule).deposit_centre == DepositCentre::robot_cell));
  if (!shortcut) return;
  const Choice ch = choose_by(rule, c, p, *rc::gen::arbitrary<uint64_t>(), *rc::gen::inRange<int64_t>(0, 70000),
                              *rc::gen::inRange(0, 1000));
  RC_ASSERT(same_decision(*shortcut, decide(rules_of(rule), current, c, ch)));
}

TEST(Rng, KeyDependsOnEveryComponentAndIndexIsInRange) {
  const uint64_t k = rng_key(7, 3, 2, Purpose::tie_break);
  EXPECT_EQ(k, rng_key(7, 3, 2, Purpose::tie_break));
  EXPECT_NE(k, rng_key(8, 3, 2, Purpose::tie_break));
  EXPECT_NE(k, rng_key(7, 4, 2, Purpose::tie_break));
  EXPECT_NE(k, rng_key(7, 3, 1, Purpose::tie_break));
  EXPECT_NE(k, rng_key(7, 3, 2, Purpose::fallback));
  EXPECT_EQ(uniform_index(0, 5), 0u);
  EXPECT_EQ(uniform_index(~uint64_t{0}, 5), 4u);
}
