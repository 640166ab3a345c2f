#pragma once
// One robot's planning decision (DESIGN.md A2, spec/SPEC.md section 3): pure functions over the
// candidate list in raster order; they know nothing of grids. The rule set's row
// (rule_set.hpp) says which best rule, fallback rule and effects apply.
//
// Candidate: an in-map cell of the window other than the robot's own, with the current
// pheromone `tau` and whether it is `blocked` (obstacle, or a robot's cell). A Choice names the
// best candidate and the target the robot moves to (-1: it stays).
//
// BestRule::thesis_normalised: probN = pow(tau, phi) * pow(eta, lambda); sum = the probN in scan
//     order; best starts at pow(1000, phi) * pow(eta, lambda) / sum and a candidate becomes best
//     when probN / sum <= best (the last of equal minima wins). No candidate qualifies (sum 0 or
//     NaN): the last candidate (every one tied).
// BestRule::last_minimum: key = pow(tau, phi) (eta^lambda / sum is common to all, so it cannot
//     change the order, but rounding could make distinct keys equal); the last minimum wins.
// BestRule::uniform_minimum: key as above; uniform among all minima (Purpose::tie_break).
// FallbackRule::first_free: a blocked best falls back to the first free candidate, else stay.
// FallbackRule::uniform_free: to a uniform free candidate (Purpose::fallback), else stay.
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <utility>

#include "spec/exploration/neighbourhood.hpp"
#include "spec/exploration/rule_set.hpp"
#include "spec/exploration/types.hpp"
#include "spec/util/num.hpp"

namespace swarmcheck::exploration {

// The rules are written once over a domain D (spec/util/num.hpp) and instantiated in
// choice.cpp for num::Concrete (what runs) and num::Symbolic (what proofs/ proves).

struct Candidate {
  CellIndex cell;
  double tau;      // current pheromone
  bool blocked;    // obstacle or occupied
};

// A symbolic candidate may be absent (a window cell outside a symbolic map): the rules skip
// it. A concrete candidate list holds only present cells.
struct SymbolicCandidate {
  CellOf<num::Symbolic> cell;
  sym::Real tau;
  sym::Bool blocked;
  sym::Bool present = true;
};

template <class D>
using CandidateOf = std::conditional_t<num::is_concrete<D>, Candidate, SymbolicCandidate>;

template <class D>
struct ChoiceT {
  typename D::Int best = -1;     // index into the candidates of the best; -1 if there are none
  typename D::Int target = -1;   // index of the cell moved to; -1: the robot stays
  typename D::Bool fallback = false;   // the best was blocked and target is a free substitute
};
using Choice = ChoiceT<num::Concrete>;

// The parts of the choice that depend only on the parameters: computed once per run.
template <class D>
struct ChoiceTermsT {
  typename D::Real phi;
  typename D::Real eta_term;            // pow(eta, lambda), the same for every cell
  typename D::Real thesis_best_start;   // pow(1000, phi) * eta_term (divided by each robot's sum)
};
using ChoiceTerms = ChoiceTermsT<num::Concrete>;
ChoiceTerms choice_terms(const Params& p);

// pow(tau, phi), with the exact shortcuts pow(x, 1) = x and pow(x, 0) = 1 (IEEE 754 pow:
// the result is exactly representable, so a pow accurate to within an ulp returns it).
template <class D>
typename D::Real pheromone_key_rule(const typename D::Real& tau, const typename D::Real& phi) {
  using Real = typename D::Real;
  return num::branch(phi == 1.0, [&] { return tau; },
                     [&] { return num::branch(phi == 0.0, [] { return Real(1.0); }, [&] { return num::pow(tau, phi); }); });
}
inline double pheromone_key(double tau, double phi) { return pheromone_key_rule<num::Concrete>(tau, phi); }

// Where a decision draws its random numbers from (only the uniform rules draw).
struct DrawSite {
  uint64_t seed;
  int64_t tick;
  int32_t robot;
};
// In a proof a draw is a free choice in its range, named after its site.
struct SymbolicDrawSite {
  std::string name;
};
template <class D>
using DrawSiteOf = std::conditional_t<num::is_concrete<D>, DrawSite, SymbolicDrawSite>;

// The choice of one robot: the rule set's best rule, then its fallback rule if the best is blocked.
template <class D>
ChoiceT<D> choose_rule(const RuleDescriptor& rules, const ChoiceTermsT<D>& terms,
                       std::span<const CandidateOf<D>> candidates, const DrawSiteOf<D>& site);

// The symbolic choice (choose_rule in the symbolic domain, its fields traced as choose_rule's).
ChoiceT<num::Symbolic> choose(const RuleDescriptor& rules, const ChoiceTermsT<num::Symbolic>& terms,
                              std::span<const SymbolicCandidate> candidates, const SymbolicDrawSite& site);

// The draw site of robot r's decision at tick `tick` (a symbolic one is named after both).
template <class D>
DrawSiteOf<D> draw_site(uint64_t seed, int64_t tick, int32_t robot) {
  if constexpr (num::is_concrete<D>)
    return DrawSite{seed, tick, robot};
  else
    return SymbolicDrawSite{"robot" + std::to_string(robot) + "@" + std::to_string(tick)};
}

// The concrete choice, written into `out`. (Returned by value from another translation unit, a
// Choice was assembled on the stack by GCC 12 and loaded back as one 8-byte word from two 4-byte
// stores, a store-forwarding stall that was a third of the choice's time in a profile; choose()
// below is inline, so its caller reads the fields one by one.)
void choose_into(const RuleDescriptor& rules, const ChoiceTerms& terms, std::span<const Candidate> candidates,
                 const DrawSite& site, Choice& out);
inline Choice choose(const RuleDescriptor& rules, const ChoiceTerms& terms, std::span<const Candidate> candidates,
                     const DrawSite& site) {
  Choice ch;
  choose_into(rules, terms, candidates, site, ch);
  return ch;
}

// What one robot's decision does to the map, from its choice and the rule set's effects.
template <class D>
struct RobotDecisionT {
  typename D::Bool moves = false;      // the robot's cell becomes `to` (waypoint: its centre); the old cell is released
  CellOf<D> to{};
  typename D::Bool occupies = false;   // `to` becomes occupied by the robot
  typename D::Bool marks = false;      // `mark` is marked visited (counted if it was not)
  CellOf<D> mark{};
  CellOf<D> deposit_centre{};
};
using RobotDecision = RobotDecisionT<num::Concrete>;

// The decision of a robot in `current` from its candidates and its choice (decide.cpp
// instantiates it for both domains).
template <class D>
RobotDecisionT<D> decide_rule(const RuleDescriptor& rules, const CellOf<D>& current,
                              std::span<const CandidateOf<D>> candidates, const ChoiceT<D>& choice);

RobotDecision decide(const RuleDescriptor& rules, CellIndex current, std::span<const Candidate> candidates,
                     const Choice& choice);
RobotDecisionT<num::Symbolic> decide(const RuleDescriptor& rules, const CellOf<num::Symbolic>& current,
                                     std::span<const SymbolicCandidate> candidates, const ChoiceT<num::Symbolic>& choice);

inline RobotDecisionT<num::Symbolic> merge(const sym::Bool& c, const RobotDecisionT<num::Symbolic>& a,
                                           const RobotDecisionT<num::Symbolic>& b) {
  auto cell = [&](const CellOf<num::Symbolic>& x, const CellOf<num::Symbolic>& y) {
    return CellOf<num::Symbolic>{sym::select(c, x[0], y[0]), sym::select(c, x[1], y[1])};
  };
  return {sym::select(c, a.moves, b.moves), cell(a.to, b.to),     sym::select(c, a.occupies, b.occupies),
          sym::select(c, a.marks, b.marks), cell(a.mark, b.mark), cell(a.deposit_centre, b.deposit_centre)};
}
inline ChoiceT<num::Symbolic> merge(const sym::Bool& c, const ChoiceT<num::Symbolic>& a, const ChoiceT<num::Symbolic>& b) {
  return {sym::select(c, a.best, b.best), sym::select(c, a.target, b.target), sym::select(c, a.fallback, b.fallback)};
}

// The decision of a robot in `current` none of whose candidates is free (every window cell
// blocked, or none in the map), for rule sets whose decision then depends on nothing else:
// choose_rule gives no target (its target is a free candidate or none: the choice lemma of the
// occupancy obligation, proved by Z3 for the deterministic and stochastic rule sets at s_range
// 1..3; a property test in tests/exploration checks it on lists of 0..48), so decide() keeps
// the robot where it is, marks nothing and deposits around `current`, whatever the pheromone.
// nullopt where the deposit centre is the best candidate (it depends on the pheromone), or the
// rule set is not one the lemma covers. Lets an implementation skip a walled-in robot's choice.
std::optional<RobotDecision> walled_in_decision(const RuleDescriptor& rules, CellIndex current);

}  // namespace swarmcheck::exploration
