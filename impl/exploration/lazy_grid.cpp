#include "impl/exploration/lazy_grid.hpp"

#include <algorithm>

#include "spec/exploration/trace.hpp"

namespace swarmcheck::impl {

namespace {
double decay_per_step(const exploration::Params& p) {
  if constexpr (kMutant == 4) return 1.0 - p.ertu * p.step_size;   // fault: no clamp at 0
  return exploration::evaporation_factor(p);
}
}  // namespace

LazyGrid::LazyGrid(const exploration::Scenario& s)
    : n_(s.map_size),
      dense_(s.rule == exploration::RuleSet::thesis),
      ertu_dt_(s.params.ertu * s.params.step_size),
      decay_(exploration::make_decay_table(std::clamp(decay_per_step(s.params), 0.0, 1.0))) {
  if constexpr (kMutant == 4) {
    // The unclamped factor may be negative: build the table by hand from it.
    const double f = decay_per_step(s.params);
    decay_.pow2[0] = f;
    for (std::size_t i = 1; i < decay_.pow2.size(); ++i) decay_.pow2[i] = decay_.pow2[i - 1] * decay_.pow2[i - 1];
  }
  cells_ = HugePageArray<CellData>(static_cast<std::size_t>(n_) * static_cast<std::size_t>(n_), CellData{});
  decay_cache_.resize(static_cast<std::size_t>(kDecayCacheSize));
  for (int64_t k = 0; k < kDecayCacheSize; ++k)
    decay_cache_[static_cast<std::size_t>(k)] = exploration::decay_factor(decay_, k);
}

void LazyGrid::evaporate_dense() {
  for (CellData& c : cells_) {
    double& v = c.value;
    if constexpr (kMutant == 4)
      v -= ertu_dt_ * v;
    else
      v = exploration::thesis_evaporate(v, ertu_dt_);
  }
}

uint64_t LazyGrid::digest(int64_t tick) const {
  exploration::Fnv1a h;
  for (std::size_t k = 0; k < cells_.size(); ++k) h.add(current(k, tick));
  return h.h;
}

}  // namespace swarmcheck::impl
