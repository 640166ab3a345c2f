#pragma once
// LazyGrid: the grid as structure-of-arrays with lazily evaluated evaporation.
// A cell holds (value, tick written); its pheromone at tick t is value * F(t - written) with the
// spec's decay function F (spec/exploration/decay.hpp), evaluated only when the cell is read or
// written. The thesis rule set's literal update cannot be expressed through F, so it stays
// dense: evaporate_dense() every step, and `value` is always current.
// A cell's fields sit together (one 16-byte record) so that a robot's window costs a few cache
// lines even on maps far larger than the cache; F(k) for small ages comes from a table filled by
// the spec's own decay_factor, so the bits are the same.
#include <cstdint>
#include <vector>

#include "impl/exploration/huge_page_array.hpp"
#include "impl/exploration/mutants.hpp"
#include "spec/exploration/decay.hpp"
#include "spec/exploration/types.hpp"

namespace swarmcheck::impl {

class LazyGrid {
 public:
  LazyGrid(const exploration::Scenario& s);

  std::size_t index(int32_t i, int32_t j) const {
    return static_cast<std::size_t>(i) * static_cast<std::size_t>(n_) + static_cast<std::size_t>(j);
  }
  int32_t size() const { return n_; }

  double current(std::size_t k, int64_t tick) const {
    const CellData& c = cells_[k];
    if (dense_ || c.value == 0.0) return c.value;   // +0 * F(k) = +0: F(k) >= 0 is finite
    return c.value * decay(tick - c.written);
  }
  // F(age), bit for bit the spec's: F multiplies P[i] over the set bits of age in increasing i,
  // so the table's F(age mod 4096) is exactly the product so far, continued over the high bits.
  double decay(int64_t age) const {
    double acc = decay_cache_[static_cast<std::size_t>(age & (kDecayCacheSize - 1))];
    auto bits = static_cast<uint64_t>(age) >> kDecayCacheBits;
    for (std::size_t i = kDecayCacheBits; bits != 0; ++i, bits >>= 1)
      if (bits & 1U) acc *= decay_.pow2[i];
    return acc;
  }
  void deposit(std::size_t k, int64_t tick, double amount) {
    cells_[k].value = current(k, tick) + amount;
    cells_[k].written = static_cast<int32_t>(tick);
  }
  // thesis rule set: the literal per-step update on every cell.
  void evaporate_dense();
  bool dense() const { return dense_; }

  bool visited(std::size_t k) const { return cells_[k].occupancy & kVisitedBit; }
  bool obstacle(std::size_t k) const { return cells_[k].occupancy & kObstacleBit; }
  // Marks a cell visited; true if it was not before.
  bool mark_visited(std::size_t k) {
    if (cells_[k].occupancy & kVisitedBit) return false;
    cells_[k].occupancy |= kVisitedBit;
    return true;
  }
  void set_obstacle(std::size_t k) { cells_[k].occupancy |= kObstacleBit; }
  int32_t occupant(std::size_t k) const { return static_cast<int32_t>(cells_[k].occupancy & kRobotMask) - 1; }
  void set_occupant(std::size_t k, int32_t r) {
    cells_[k].occupancy = (cells_[k].occupancy & ~kRobotMask) | static_cast<uint32_t>(r + 1);
  }
  // An obstacle or a robot: any bit but `visited`.
  bool blocked(std::size_t k) const { return (cells_[k].occupancy & ~kVisitedBit) != 0; }

  // Asks the memory system for cells [k, k + count) ahead of use (no effect on results).
  void prefetch(std::size_t k, std::size_t count) const {
    __builtin_prefetch(&cells_[k]);
    __builtin_prefetch(&cells_[k + count - 1]);
  }

  uint64_t digest(int64_t tick) const;   // FNV-1a over every current value, raster order

 private:
  // 16 bytes: four cells to a cache line. Ticks fit 31 bits (kStepsMax); robot indices 30 bits
  // (kRobotsMax): the two top bits of `occupancy` are the flags, the rest is robot index + 1.
  struct CellData {
    double value = 0.0;       // pheromone as written at `written`
    int32_t written = 0;      // tick of the last write
    uint32_t occupancy = 0;   // kVisitedBit | kObstacleBit | (robot index + 1, or 0)
  };
  static constexpr uint32_t kVisitedBit = 1U << 31;
  static constexpr uint32_t kObstacleBit = 1U << 30;
  static constexpr uint32_t kRobotMask = kObstacleBit - 1;
  static constexpr int kDecayCacheBits = 12;
  static constexpr int64_t kDecayCacheSize = int64_t{1} << kDecayCacheBits;

  int32_t n_;
  bool dense_;
  double ertu_dt_;
  exploration::DecayTable decay_;
  std::vector<double> decay_cache_;   // F(k) for k < kDecayCacheSize
  HugePageArray<CellData> cells_;
};

}  // namespace swarmcheck::impl
