#include "model/exploration/dense_grid.hpp"

namespace swarmcheck::model::exploration {

DenseGrid::DenseGrid(const EnvironmentConfig& cfg) : cfg_(&cfg), n_(cfg.scenario.map_size) {
  const auto cells = static_cast<Eigen::Index>(int64_t{n_} * n_);
  value_ = Eigen::ArrayXd::Zero(cells);
  written_ = Eigen::Array<int64_t, Eigen::Dynamic, 1>::Zero(cells);
  current_ = Eigen::ArrayXd::Zero(cells);
  visited_ = Eigen::Array<bool, Eigen::Dynamic, 1>::Constant(cells, false);
  obstacle_ = Eigen::Array<bool, Eigen::Dynamic, 1>::Constant(cells, false);
  occupant_ = Eigen::ArrayXi::Constant(cells, -1);
}

void DenseGrid::evaporate(int64_t tick) {
  SWARM_DEMAND(tick == tick_ + 1);
  tick_ = tick;
  for (Eigen::Index k = 0; k < current_.size(); ++k) {
    if (cfg_->rules->evaporation == Evaporation::literal_per_step) {
      current_[k] = thesis_evaporate(current_[k], cfg_->ertu_dt);
      value_[k] = current_[k];
      written_[k] = tick_;
    } else {
      current_[k] = decayed_pheromone(value_[k], decay_factor(cfg_->decay, tick_ - written_[k]));
    }
  }
}

void DenseGrid::deposit(CellIndex c, int64_t tick, double amount) {
  SWARM_DEMAND(tick == tick_);
  const Eigen::Index k = index(c);
  current_[k] = deposited_pheromone(current_[k], amount);
  value_[k] = current_[k];
  written_[k] = tick_;
}

Cell DenseGrid::cell(CellIndex c) const {
  const Eigen::Index k = index(c);
  return Cell{current_[k], tick_, visited_[k], obstacle_[k], occupant_[k]};
}

}  // namespace swarmcheck::model::exploration
