#pragma once
// The reference model's grid: dense, one entry per cell, every cell's pheromone evaluated on
// every step (the obvious way). It implements the grid of spec/exploration/environment_step.hpp.
//   decay function:   a cell holds (value, tick written); evaporate(t) sets every cell's
//                     current = value * F(t - written) with the spec's decay_factor
//   literal update:   evaporate(t) applies the thesis's ph -= ertu dt ph; clamp to every cell
#include <Eigen/Core>
#include <cstdint>

#include "spec/exploration/environment_step.hpp"
#include "spec/util/demand.hpp"

namespace swarmcheck::model::exploration {

using namespace swarmcheck::exploration;

class DenseGrid {
 public:
  explicit DenseGrid(const EnvironmentConfig& cfg);
  // The bytes the arrays of an n x n map take (the memory budget's estimate).
  static std::uint64_t bytes_for(int32_t n) {
    return std::uint64_t(n) * std::uint64_t(n) *
           (2 * sizeof(double) + sizeof(int64_t) + 2 * sizeof(bool) + sizeof(int));
  }

  Candidate candidate(CellIndex c, int64_t tick) const {
    const Eigen::Index k = index(c);
    return Candidate{c, pheromone(c, tick), obstacle_[k] || occupant_[k] >= 0};
  }
  double pheromone(CellIndex c, int64_t tick) const {
    SWARM_DEMAND(tick == tick_);   // current_ holds every cell's value at tick_
    return current_[index(c)];
  }
  void release(CellIndex c) { occupant_[index(c)] = -1; }
  void occupy(CellIndex c, int32_t r) {
    SWARM_DEMAND(!obstacle_[index(c)]);
    occupant_[index(c)] = r;
  }
  bool mark_visited(CellIndex c) {
    const Eigen::Index k = index(c);
    const bool newly = !visited_[k];
    visited_[k] = true;
    return newly;
  }
  void set_obstacle(CellIndex c) { obstacle_[index(c)] = true; }
  void evaporate(int64_t tick);
  void deposit(CellIndex c, int64_t tick, double amount);

  // One cell as the public Cell type, its pheromone current at tick_.
  Cell cell(CellIndex c) const;
  // The tick of the cell's last write (its value's age is tick_ minus this): for the harness's
  // coverage figures, not part of the observable state.
  int64_t written_tick(CellIndex c) const { return written_[index(c)]; }

 private:
  Eigen::Index index(CellIndex c) const {
    SWARM_DEMAND(in_map(c, n_));
    return static_cast<Eigen::Index>(int64_t{c[0]} * n_ + c[1]);
  }

  const EnvironmentConfig* cfg_;
  int32_t n_;
  int64_t tick_ = 0;
  Eigen::ArrayXd value_;      // pheromone as written at written_[k]
  Eigen::Array<int64_t, Eigen::Dynamic, 1> written_;
  Eigen::ArrayXd current_;    // every cell's value at tick_
  Eigen::Array<bool, Eigen::Dynamic, 1> visited_;
  Eigen::Array<bool, Eigen::Dynamic, 1> obstacle_;
  Eigen::ArrayXi occupant_;   // robot index or -1
};

}  // namespace swarmcheck::model::exploration
