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
//
// Every rule is written once over a domain D (spec/util/num.hpp) and instantiated in decay.cpp
// for num::Concrete (what model/ and impl/ run) and num::Symbolic (what proofs/ proves). The two
// loops (the table's and F's) call their bodies as rules of their own, so that a proof can take
// them by induction, for every table entry and every age; impl/'s LazyGrid continues F over the
// high bits of an age with decay_factor_from, the same loop.
#include <array>
#include <cstddef>
#include <cstdint>

#include "spec/exploration/types.hpp"
#include "spec/util/num.hpp"

namespace swarmcheck::exploration {

// The evaporation factor per step, f = max(0, 1 - ertu * step_size).
template <class D>
typename D::Real evaporation_factor_rule(const typename D::Real& ertu, const typename D::Real& step_size);

// The thesis's updatePheromone for one cell: ph -= (ertu * step_size) * ph; clamp at 0.
template <class D>
typename D::Real thesis_evaporate_rule(const typename D::Real& ph, const typename D::Real& ertu_times_dt);

// The decay table's loop body: P[i+1] from P[i].
template <class D>
typename D::Real decay_square_rule(const typename D::Real& p);

// The decay function's loop body: the product so far, times P[i] (bit i of the age is set).
template <class D>
typename D::Real decay_step_rule(const typename D::Real& acc, const typename D::Real& p);

template <class D>
struct DecayTableT {
  std::array<typename D::Real, 63> pow2{};   // pow2[i] = f^(2^i); k < 2^63
};
using DecayTable = DecayTableT<num::Concrete>;

// P[0] = f, P[i] = decay_square_rule(P[i - 1]).
template <class D>
DecayTableT<D> make_decay_table_rule(const typename D::Real& f);

// F's loop from `first_bit` on: acc times P[i] for every set bit i of bits << first_bit.
template <class D>
typename D::Real decay_factor_from_rule(const DecayTableT<D>& table, typename D::Real acc, uint64_t bits,
                                        std::size_t first_bit);

// F(k) = decay_factor_from_rule(table, 1.0, k, 0).
template <class D>
typename D::Real decay_factor_rule(const DecayTableT<D>& table, int64_t k);

// A cell's pheromone `factor` = F(age) after it was written: value * factor (the grids' read).
template <class D>
typename D::Real decayed_pheromone_rule(const typename D::Real& value, const typename D::Real& factor);

// ---- The concrete API. ----

// f = max(0, 1 - ertu * step_size).
double evaporation_factor(const Params& p);

DecayTable make_decay_table(double f);

// F(k), k >= 0.
double decay_factor(const DecayTable& table, int64_t k);

// F's loop continued: acc times P[i] for the set bits i >= first_bit of (bits << first_bit), as
// decay_factor multiplies them. A table of F for the low bits continues with this.
double decay_factor_from(const DecayTable& table, double acc, uint64_t bits, std::size_t first_bit);

inline double decayed_pheromone(double value, double factor) {
  return decayed_pheromone_rule<num::Concrete>(value, factor);
}

// The thesis's updatePheromone for one cell: ph -= (ertu * step_size) * ph; clamp at 0.
double thesis_evaporate(double ph, double ertu_times_dt);

// thesis_evaporate on `count` values `stride_bytes` apart (the hot loop of a thesis run: one call
// per grid, the rule inlined into the loop in decay.cpp).
void thesis_evaporate_each(double* first, std::size_t count, std::size_t stride_bytes, double ertu_times_dt);

}  // namespace swarmcheck::exploration
