#include "spec/exploration/decay.hpp"

#include <algorithm>

#include "spec/util/demand.hpp"

namespace swarmcheck::exploration {

double evaporation_factor(const Params& p) {
  const double f = std::max(0.0, 1.0 - p.ertu * p.step_size);
  SWARM_DEMAND(f >= 0.0 && f <= 1.0);
  return f;
}

DecayTable make_decay_table(double f) {
  SWARM_DEMAND(f >= 0.0 && f <= 1.0);
  DecayTable t;
  t.pow2[0] = f;
  for (std::size_t i = 1; i < t.pow2.size(); ++i) t.pow2[i] = t.pow2[i - 1] * t.pow2[i - 1];
  return t;
}

double decay_factor(const DecayTable& table, int64_t k) {
  SWARM_DEMAND(k >= 0);
  double acc = 1.0;
  auto bits = static_cast<uint64_t>(k);
  for (std::size_t i = 0; bits != 0; ++i, bits >>= 1)
    if (bits & 1U) acc *= table.pow2[i];
  return acc;
}

}  // namespace swarmcheck::exploration
