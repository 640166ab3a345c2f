#pragma once
// LazyGrid: the grid of spec/exploration/environment_step.hpp with lazily evaluated evaporation.
// A cell holds (value, tick written); its pheromone at tick t is value * F(t - written) with the
// spec's decay function F (spec/exploration/decay.hpp), evaluated only when the cell is read or
// written, so a step costs the robots' windows, not the map. The thesis's literal update cannot
// be expressed through F, so under it the grid is dense: every cell every step, and `value` is
// always current.
// A cell's fields sit together (one 16-byte record) so that a robot's window costs a few cache
// lines even on maps far larger than the cache; F(k) for small ages comes from a table filled by
// the spec's own decay_factor, so the bits are the same.
#include <cstdint>
#include <vector>

#include "impl/exploration/huge_page_array.hpp"
#include "spec/exploration/environment_step.hpp"
#include "spec/util/demand.hpp"

namespace swarmcheck::impl::exploration {

using swarmcheck::exploration::Candidate;
using swarmcheck::exploration::CellIndex;

class LazyGrid {
 public:
  explicit LazyGrid(const swarmcheck::exploration::EnvironmentConfig& cfg);
  // The bytes the cells of an n x n map take (the memory budget's estimate).
  static std::uint64_t bytes_for(int32_t n) { return std::uint64_t(n) * std::uint64_t(n) * sizeof(CellData); }

  // The grid operations of the spec's Environment step.
  Candidate candidate(CellIndex c, int64_t tick) const {
    const std::size_t k = index(c);
    return Candidate{c, current(k, tick), blocked(k)};
  }
  double pheromone(CellIndex c, int64_t tick) const { return current(index(c), tick); }
  void release(CellIndex c) { set_occupant(index(c), -1); }
  void occupy(CellIndex c, int32_t r) {
    SWARM_ASSERT(!obstacle(index(c)));
    set_occupant(index(c), r);
  }
  bool mark_visited(CellIndex c) {
    CellData& cell = cells_[index(c)];
    if (cell.occupancy & kVisitedBit) return false;
    cell.occupancy |= kVisitedBit;
    return true;
  }
  void set_obstacle(CellIndex c) { cells_[index(c)].occupancy |= kObstacleBit; }
  // Lazy cells need nothing: every read names its tick. Literal cells are updated in place.
  void evaporate(int64_t /*tick*/) {
    if (dense_) evaporate_dense();
  }
  void deposit(CellIndex c, int64_t tick, double amount) { deposit_at(cells_[index(c)], tick, amount); }

  swarmcheck::exploration::Cell cell(CellIndex c, int64_t tick) const;

  // spec::gather_candidates's list (the window of c without c, raster order, pheromone at tick),
  // row by row: the index worked out once a row instead of once a cell.
  template <class Alloc>
  void gather_window(const swarmcheck::exploration::EnvironmentConfig& cfg, CellIndex c, int64_t tick,
                     std::vector<Candidate, Alloc>& out) const {
    out.clear();
    const swarmcheck::exploration::Window w = swarmcheck::exploration::window_around(c, cfg.scenario.params.s_range, n_);
    for (int32_t i = w.i_lo; i <= w.i_hi; ++i) {
      const CellData* cell = &cells_[index(CellIndex{i, w.j_lo})];
      for (int32_t j = w.j_lo; j <= w.j_hi; ++j, ++cell)
        if (i != c[0] || j != c[1]) out.push_back(Candidate{CellIndex{i, j}, current_of(*cell, tick), blocked_of(*cell)});
    }
  }

  // spec::deposit_around(cfg, *this, centre, tick), row by row: the same cells, each given
  // deposit(c, tick, kernel amount) once with the same bits (a window's cells are distinct, so
  // the order among them cannot matter), with the index and the kernel's row worked out once a
  // row instead of once a cell. (The generic loop reloaded the kernel and recomputed the index
  // and offsets at every cell: most of the deposit stage's time.)
  void deposit_window(const swarmcheck::exploration::EnvironmentConfig& cfg, CellIndex centre, int64_t tick) {
    const swarmcheck::exploration::DepositKernel& kernel = cfg.deposit;
    const swarmcheck::exploration::Window w = swarmcheck::exploration::window_around(centre, cfg.scenario.params.s_range, n_);
    for (int32_t i = w.i_lo; i <= w.i_hi; ++i) {
      const double* amounts = kernel.row(i - centre[0]);
      if (!amounts) {   // a window too big to table: the spec's loop for this row
        for (int32_t j = w.j_lo; j <= w.j_hi; ++j) deposit(CellIndex{i, j}, tick, kernel.amount(i - centre[0], j - centre[1]));
        continue;
      }
      amounts += w.j_lo - centre[1] + kernel.radius();
      CellData* cell = &cells_[index(CellIndex{i, w.j_lo})];
      for (int32_t j = w.j_lo; j <= w.j_hi; ++j, ++cell, ++amounts) deposit_at(*cell, tick, *amounts);
    }
  }

  // Whether every cell of c's window is blocked (an obstacle or a robot's cell): for a robot in c
  // (its own cell blocked), whether it has no free candidate.
  bool window_blocked(CellIndex c, int32_t s_range) const {
    const swarmcheck::exploration::Window w = swarmcheck::exploration::window_around(c, s_range, n_);
    // Out at the first free cell: in a sparse swarm that is the first cell looked at, so the
    // test costs robots that are not walled in next to nothing.
    for (int32_t i = w.i_lo; i <= w.i_hi; ++i) {
      const CellData* cell = &cells_[index(CellIndex{i, w.j_lo})];
      for (int32_t j = w.j_lo; j <= w.j_hi; ++j, ++cell)
        if (!blocked_of(*cell)) return false;
    }
    return true;
  }

  // Asks the memory system for the rows of c's window ahead of use (no effect on results).
  void prefetch_window(CellIndex c, int32_t s_range) const;

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

  std::size_t index(CellIndex c) const {
    SWARM_ASSERT(swarmcheck::exploration::in_map(c, n_));
    return static_cast<std::size_t>(c[0]) * static_cast<std::size_t>(n_) + static_cast<std::size_t>(c[1]);
  }
  double current(std::size_t k, int64_t tick) const { return current_of(cells_[k], tick); }
  // The one place a deposit writes a cell (deposit() and deposit_window()).
  void deposit_at(CellData& cell, int64_t tick, double amount) {
    cell.value = swarmcheck::exploration::deposited_pheromone(current_of(cell, tick), amount);
    cell.written = static_cast<int32_t>(tick);
  }
  double current_of(const CellData& c, int64_t tick) const {
    if (dense_ || c.value == 0.0) return c.value;   // +0 * F(k) = +0: F(k) >= 0 is finite
    return swarmcheck::exploration::decayed_pheromone(c.value, decay(tick - c.written));
  }
  // F(age), bit for bit the spec's: F multiplies P[i] over the set bits of age in increasing i,
  // so the table's F(age mod 4096) is exactly the product so far, continued over the high bits by
  // the spec's own loop (decay_factor_from, which the proofs take by induction).
  double decay(int64_t age) const {
    const double low = decay_cache_[static_cast<std::size_t>(age & (kDecayCacheSize - 1))];
    const uint64_t high = static_cast<uint64_t>(age) >> kDecayCacheBits;
    return high == 0 ? low : swarmcheck::exploration::decay_factor_from(*decay_, low, high, kDecayCacheBits);
  }
  bool obstacle(std::size_t k) const { return cells_[k].occupancy & kObstacleBit; }
  // An obstacle or a robot: any bit but `visited`.
  bool blocked(std::size_t k) const { return blocked_of(cells_[k]); }
  static bool blocked_of(const CellData& c) { return (c.occupancy & ~kVisitedBit) != 0; }
  void set_occupant(std::size_t k, int32_t r) {
    cells_[k].occupancy = (cells_[k].occupancy & ~kRobotMask) | static_cast<uint32_t>(r + 1);
  }
  void evaporate_dense();

  int32_t n_;
  bool dense_;
  double ertu_dt_;
  const swarmcheck::exploration::DecayTable* decay_;
  std::vector<double> decay_cache_;   // F(k) for k < kDecayCacheSize
  HugePageArray<CellData> cells_;
};

}  // namespace swarmcheck::impl::exploration
