#pragma once
// The choice of a robot's next cell among its candidates (DESIGN.md A2). Pure functions over
// the candidate list in raster order; they know nothing of grids or robots.
//
// Candidate: an in-map cell of the window other than the robot's own, with the current
// pheromone `tau` and whether it is `blocked` (obstacle, or a robot's cell). A Choice names the
// best (minimum-score) candidate and the target the robot moves to (-1: it stays).
//
// thesis:        probN = pow(tau, phi) * pow(eta, lambda); sum = the probN in scan order;
//                best starts at pow(1000, phi) * pow(eta, lambda) / sum and a candidate
//                becomes best when probN / sum <= best (the last of equal minima wins).
//                No candidate qualifies (sum 0 or NaN): the last candidate (every one tied).
//                Blocked best: the first free candidate, else stay.
// deterministic: key = pow(tau, phi) (eta^lambda / sum is common to all, so it cannot change
//                the order, but rounding could make distinct keys equal); the last minimum in
//                scan order wins; blocked best: the first free candidate, else stay.
// stochastic:    key as deterministic; uniform among all minima (Purpose::tie_break);
//                blocked best: a uniform free candidate (Purpose::fallback), else stay.
#include <cstdint>
#include <span>

#include "spec/exploration/types.hpp"

namespace swarmcheck::exploration {

struct Candidate {
  CellIndex cell;
  double tau;      // current pheromone
  bool blocked;    // obstacle or occupied
};

struct Choice {
  int32_t best = -1;     // index into the candidates of the minimum; -1 if there are none
  int32_t target = -1;   // index of the cell moved to; -1: the robot stays
  bool fallback = false; // the best was blocked and target is a free substitute
};

Choice choose_thesis(std::span<const Candidate> candidates, const Params& p);
Choice choose_deterministic(std::span<const Candidate> candidates, const Params& p);
// tie_key and fallback_key: rng_key(seed, tick, robot, Purpose::tie_break / ::fallback).
Choice choose_stochastic(std::span<const Candidate> candidates, const Params& p,
                         uint64_t tie_key, uint64_t fallback_key);

}  // namespace swarmcheck::exploration
