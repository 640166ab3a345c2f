#pragma once
// The optimised Environment: the same step as model/exploration/environment_model.hpp (see
// spec/SPEC.md section 6), computed with a lazy grid, incremental counts and, for many robots,
// parallel decisions by independent groups.
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "impl/exploration/lazy_grid.hpp"
#include "spec/exploration/types.hpp"
#include "swarmcheck/exploration.hpp"

namespace swarmcheck::impl {

// Per-thread scratch for one robot's window; sized once, reused every step.
struct WindowScratch {
  std::vector<std::size_t> cell;
  std::vector<exploration::CellIndex> at;
  std::vector<double> tau;
  std::vector<double> key;
  std::vector<uint8_t> blocked;
};

class Environment {
 public:
  Environment(const exploration::Scenario& s, const ExplorationOptions& options);

  void step(bool all_arrived);

  const exploration::Scenario& scenario() const { return sc_; }
  const std::vector<exploration::CellIndex>& cells() const { return cell_; }
  const std::vector<exploration::Point_m>& waypoints() const { return waypoint_; }
  exploration::HandshakeState handshake() const { return handshake_; }
  int64_t tick() const { return tick_; }
  int64_t planning_steps() const { return planning_steps_; }
  int64_t visited() const { return visited_; }
  int64_t free_cells() const { return free_cells_; }
  double eP() const { return eP_; }
  double sTime() const { return sTime_; }
  std::optional<int64_t> completion_step() const { return completion_step_; }
  exploration::Cell cell(exploration::CellIndex c) const;
  uint64_t digest() const { return grid_.digest(clock_); }

 private:
  void plan();
  void plan_sequential();
  // Prefetches the rows of c's window (small windows only): robots are handled in index order,
  // so the windows of the next few are known before they are needed.
  void prefetch_window(exploration::CellIndex c) const;
  void plan_grouped();
  // One robot's decision and move; returns how many cells it newly marked visited.
  int64_t plan_robot(int32_t r, WindowScratch& w);
  void gather(exploration::CellIndex c, WindowScratch& w) const;
  int32_t choose_thesis(WindowScratch& w) const;
  int32_t choose_deterministic(const WindowScratch& w) const;
  int32_t choose_stochastic(int32_t r, WindowScratch& w) const;
  int32_t substitute(int32_t r, const WindowScratch& w) const;
  int64_t move(int32_t r, exploration::CellIndex to, bool mark);
  void deposit_around(exploration::CellIndex centre);
  double deposit_amount(int32_t di, int32_t dj) const;
  // pow(tau, phi), with the exact shortcuts pow(x, 1) = x and pow(x, 0) = 1 (IEEE 754 / C Annex F).
  double key(double tau) const {
    if (sc_.params.phi == 1.0) return tau;
    if (sc_.params.phi == 0.0) return 1.0;
    return std::pow(tau, sc_.params.phi);
  }
  void update_progress();

  exploration::Scenario sc_;
  ExplorationOptions options_;
  LazyGrid grid_;
  double eta_term_;                     // pow(eta, lambda), the same for every cell
  double thesis_best_start_;            // pow(1000, phi) * eta_term_ (divided by sum per robot)
  std::vector<double> deposit_table_;   // amounts by (di, dj) when the window is small
  int32_t deposit_radius_ = 0;
  std::vector<exploration::CellIndex> cell_;
  std::vector<exploration::Point_m> waypoint_;
  std::vector<exploration::CellIndex> deposit_centre_;
  std::vector<uint8_t> start_blocked_;  // mutant 6 only: occupancy as the step began
  exploration::HandshakeState handshake_;
  int64_t tick_ = 0;
  int64_t clock_ = 0;   // the grid's evaporation clock: tick_ (mutant 5: fewer)
  int64_t planning_steps_ = 0;
  int64_t visited_ = 0;
  int64_t free_cells_ = 0;
  double eP_ = 0;
  double sTime_ = 0;
  std::optional<int64_t> completion_step_;
};

}  // namespace swarmcheck::impl
