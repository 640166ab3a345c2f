#include "impl/exploration/lazy_grid.hpp"

namespace swarmcheck::impl::exploration {

using swarmcheck::exploration::Evaporation;

LazyGrid::LazyGrid(const swarmcheck::exploration::EnvironmentConfig& cfg)
    : n_(cfg.scenario.map_size),
      dense_(cfg.rules->evaporation == Evaporation::literal_per_step),
      ertu_dt_(cfg.ertu_dt),
      decay_(&cfg.decay),
      cells_(static_cast<std::size_t>(n_) * static_cast<std::size_t>(n_), CellData{}) {
  decay_cache_.resize(static_cast<std::size_t>(kDecayCacheSize));
  for (int64_t k = 0; k < kDecayCacheSize; ++k)
    decay_cache_[static_cast<std::size_t>(k)] = swarmcheck::exploration::decay_factor(cfg.decay, k);
}

swarmcheck::exploration::Cell LazyGrid::cell(CellIndex c, int64_t tick) const {
  const std::size_t k = index(c);
  const int32_t occupant = static_cast<int32_t>(cells_[k].occupancy & kRobotMask) - 1;
  return swarmcheck::exploration::Cell{current(k, tick), tick, (cells_[k].occupancy & kVisitedBit) != 0,
                                       obstacle(k), occupant};
}

void LazyGrid::prefetch_window(CellIndex c, int32_t s_range) const {
  const swarmcheck::exploration::Window w = swarmcheck::exploration::window_around(c, s_range, n_);
  for (int32_t i = w.i_lo; i <= w.i_hi; ++i) {
    __builtin_prefetch(&cells_[index(CellIndex{i, w.j_lo})]);
    __builtin_prefetch(&cells_[index(CellIndex{i, w.j_hi})]);
  }
}

void LazyGrid::evaporate_dense() {
  if (cells_.size() == 0) return;
  swarmcheck::exploration::thesis_evaporate_each(&cells_[0].value, cells_.size(), sizeof(CellData), ertu_dt_);
}

}  // namespace swarmcheck::impl::exploration
