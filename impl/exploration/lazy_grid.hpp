#pragma once
// LazyGrid: the grid as structure-of-arrays with lazily evaluated evaporation.
// A cell holds (value, tick written); its pheromone at tick t is value * F(t - written) with the
// spec's decay function F (spec/exploration/decay.hpp), evaluated only when the cell is read or
// written. The thesis rule set's literal update cannot be expressed through F, so it stays
// dense: evaporate_dense() every step, and `value` is always current.
#include <cstdint>
#include <vector>

#include "impl/exploration/mutants.hpp"
#include "spec/exploration/decay.hpp"
#include "spec/exploration/types.hpp"

namespace swarmcheck::impl {

class LazyGrid {
 public:
  static constexpr uint8_t kVisited = 1;
  static constexpr uint8_t kObstacle = 2;

  LazyGrid(const exploration::Scenario& s);

  std::size_t index(int32_t i, int32_t j) const {
    return static_cast<std::size_t>(i) * static_cast<std::size_t>(n_) + static_cast<std::size_t>(j);
  }
  int32_t size() const { return n_; }

  double current(std::size_t k, int64_t tick) const {
    if (dense_) return value_[k];
    return value_[k] * exploration::decay_factor(decay_, tick - written_[k]);
  }
  void deposit(std::size_t k, int64_t tick, double amount) {
    value_[k] = current(k, tick) + amount;
    written_[k] = tick;
  }
  // thesis rule set: the literal per-step update on every cell.
  void evaporate_dense();
  bool dense() const { return dense_; }

  bool visited(std::size_t k) const { return flags_[k] & kVisited; }
  bool obstacle(std::size_t k) const { return flags_[k] & kObstacle; }
  // Marks a cell visited; true if it was not before.
  bool mark_visited(std::size_t k) {
    if (flags_[k] & kVisited) return false;
    flags_[k] = static_cast<uint8_t>(flags_[k] | kVisited);
    return true;
  }
  void set_obstacle(std::size_t k) { flags_[k] = static_cast<uint8_t>(flags_[k] | kObstacle); }
  int32_t occupant(std::size_t k) const { return occupant_[k]; }
  void set_occupant(std::size_t k, int32_t r) { occupant_[k] = r; }
  bool blocked(std::size_t k) const { return (flags_[k] & kObstacle) || occupant_[k] >= 0; }

  uint64_t digest(int64_t tick) const;   // FNV-1a over every current value, raster order

 private:
  int32_t n_;
  bool dense_;
  double ertu_dt_;
  exploration::DecayTable decay_;
  std::vector<double> value_;
  std::vector<int64_t> written_;
  std::vector<uint8_t> flags_;
  std::vector<int32_t> occupant_;
};

}  // namespace swarmcheck::impl
