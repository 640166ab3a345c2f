#pragma once
// Evaporation as a decay function (DESIGN.md A5).
//
// Per step, tau <- max(0, tau - ertu*dt*tau). The fixed rule sets state this through a decay
// function so a lazy implementation can be bit-identical to a dense one: a cell keeps
// (value, tick written) and its value k ticks later is value * F(k), with
//   f    = max(0, 1 - ertu*dt)
//   P[0] = f,  P[i+1] = P[i] * P[i]                      (P[i] = f^(2^i), as rounded)
//   F(k) = product of P[i] over the set bits i of k, multiplied in increasing i, from 1.0
// The thesis rule set keeps the literal in-place update instead (thesis_evaporate).
#include <array>
#include <cstddef>
#include <cstdint>

#include "spec/exploration/types.hpp"
#include "spec/util/num.hpp"

namespace swarmcheck::exploration {

// The rules, once, over a domain D (spec/util/num.hpp). The evaporation factor per step,
// f = max(0, 1 - ertu * step_size) (decay.cpp instantiates it for both domains):
template <class D>
typename D::Real evaporation_factor_rule(const typename D::Real& ertu, const typename D::Real& step_size);

// The thesis's updatePheromone for one cell: ph -= (ertu * step_size) * ph; clamp at 0
// (decay.cpp instantiates it for both domains; defined there, not inline, so that the proofs
// and the executed code read the one compiled definition).
template <class D>
typename D::Real thesis_evaporate_rule(const typename D::Real& ph, const typename D::Real& ertu_times_dt);

struct DecayTable {
  std::array<double, 63> pow2{};   // pow2[i] = f^(2^i); k < 2^63
};

// f = max(0, 1 - ertu * step_size).
double evaporation_factor(const Params& p);

DecayTable make_decay_table(double f);

// F(k), k >= 0.
double decay_factor(const DecayTable& table, int64_t k);

// The thesis's updatePheromone for one cell: ph -= (ertu * step_size) * ph; clamp at 0.
double thesis_evaporate(double ph, double ertu_times_dt);

// thesis_evaporate on `count` values `stride_bytes` apart (the hot loop of a thesis run: one call
// per grid, the rule inlined into the loop in decay.cpp).
void thesis_evaporate_each(double* first, std::size_t count, std::size_t stride_bytes, double ertu_times_dt);

}  // namespace swarmcheck::exploration
