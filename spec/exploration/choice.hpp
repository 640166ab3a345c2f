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
#include <span>

#include "spec/exploration/rule_set.hpp"
#include "spec/exploration/types.hpp"

namespace swarmcheck::exploration {

struct Candidate {
  CellIndex cell;
  double tau;      // current pheromone
  bool blocked;    // obstacle or occupied
};

struct Choice {
  int32_t best = -1;     // index into the candidates of the best; -1 if there are none
  int32_t target = -1;   // index of the cell moved to; -1: the robot stays
  bool fallback = false; // the best was blocked and target is a free substitute
};

// The parts of the choice that depend only on the parameters: computed once per run.
struct ChoiceTerms {
  double phi;
  double eta_term;            // pow(eta, lambda), the same for every cell
  double thesis_best_start;   // pow(1000, phi) * eta_term (divided by each robot's sum)
};
ChoiceTerms choice_terms(const Params& p);

// pow(tau, phi), with the exact shortcuts pow(x, 1) = x and pow(x, 0) = 1 (IEEE 754 pow:
// the result is exactly representable, so a pow accurate to within an ulp returns it).
inline double pheromone_key(double tau, double phi) {
  if (phi == 1.0) return tau;
  if (phi == 0.0) return 1.0;
  return std::pow(tau, phi);
}

// Where a decision draws its random numbers from (only the uniform rules draw).
struct DrawSite {
  uint64_t seed;
  int64_t tick;
  int32_t robot;
};

Choice choose(const RuleDescriptor& rules, const ChoiceTerms& terms, std::span<const Candidate> candidates,
              const DrawSite& site);

// What one robot's decision does to the map, from its choice and the rule set's effects.
struct RobotDecision {
  bool moves = false;       // the robot's cell becomes `to` (waypoint: its centre); the old cell is released
  CellIndex to{};
  bool occupies = false;    // `to` becomes occupied by the robot
  bool marks = false;       // `mark` is marked visited (counted if it was not)
  CellIndex mark{};
  CellIndex deposit_centre{};
};

RobotDecision decide(const RuleDescriptor& rules, CellIndex current, std::span<const Candidate> candidates,
                     const Choice& choice);

}  // namespace swarmcheck::exploration
