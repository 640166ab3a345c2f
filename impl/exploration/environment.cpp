#include "impl/exploration/environment.hpp"

#include <cmath>

#include "spec/exploration/handshake.hpp"
#include "spec/exploration/neighbourhood.hpp"
#include "spec/exploration/rng.hpp"
#include "spec/util/demand.hpp"

namespace swarmcheck::impl {

using exploration::CellIndex;
using exploration::RuleSet;

namespace {
// Deposit amounts are tabulated by offset when the window has at most this many cells.
constexpr int64_t kDepositTableMax = 1 << 16;
constexpr std::size_t kPrefetchAhead = 4;   // robots
constexpr int32_t kPrefetchRangeMax = 2;    // s_range up to which windows are prefetched
}  // namespace

Environment::Environment(const exploration::Scenario& s, const ExplorationOptions& options)
    : sc_(s),
      options_(options),
      grid_(s),
      eta_term_(std::pow(s.params.eta, s.params.lambda)),
      thesis_best_start_(std::pow(1000.0, s.params.phi) * eta_term_),
      handshake_(exploration::initial_handshake()) {
  const int64_t side = 2 * int64_t{std::min(s.params.s_range, s.map_size)} + 1;
  if (side * side <= kDepositTableMax) {
    deposit_radius_ = static_cast<int32_t>((side - 1) / 2);
    for (int32_t di = -deposit_radius_; di <= deposit_radius_; ++di)
      for (int32_t dj = -deposit_radius_; dj <= deposit_radius_; ++dj)
        deposit_table_.push_back(exploration::deposit_amount(s.params, di, dj));
  }
  for (std::size_t r = 0; r < s.robots.size(); ++r) {
    const CellIndex c = exploration::cell_of(s.robots[r], s.cell_size);
    cell_.push_back(c);
    waypoint_.push_back(s.robots[r]);
    deposit_around(c);
    const std::size_t k = grid_.index(c[0], c[1]);
    grid_.set_occupant(k, static_cast<int32_t>(r));
    visited_ += grid_.mark_visited(k) ? 1 : 0;
  }
  for (const CellIndex& c : s.obstacles) grid_.set_obstacle(grid_.index(c[0], c[1]));
  free_cells_ = exploration::free_cell_count(s);
  deposit_centre_.resize(cell_.size());
  update_progress();
}

exploration::Cell Environment::cell(CellIndex c) const {
  SWARM_DEMAND(exploration::in_map(c, sc_.map_size));
  const std::size_t k = grid_.index(c[0], c[1]);
  return exploration::Cell{grid_.current(k, clock_), clock_, grid_.visited(k), grid_.obstacle(k),
                           grid_.occupant(k)};
}

void Environment::step(bool all_arrived) {
  bool planning = true;
  if (sc_.mode == exploration::Mode::cosim) {
    const exploration::HandshakeStep hs = exploration::environment_handshake(handshake_, all_arrived);
    planning = hs.plan;
    handshake_ = hs.next;
  }
  if (planning) plan();
  ++tick_;
  const bool skip_evaporation = kMutant == 5 && planning;   // fault 5
  if (!skip_evaporation) {
    ++clock_;
    if (grid_.dense()) grid_.evaporate_dense();
  }
  if (planning) {
    const std::size_t n = deposit_centre_.size();
    for (std::size_t r = 0; r < n; ++r) {
      if (r + kPrefetchAhead < n) prefetch_window(deposit_centre_[r + kPrefetchAhead]);
      deposit_around(deposit_centre_[r]);
    }
    ++planning_steps_;
  }
  update_progress();
}

void Environment::plan() {
  if constexpr (kMutant == 6) {
    start_blocked_.assign(static_cast<std::size_t>(sc_.map_size) * static_cast<std::size_t>(sc_.map_size), 0);
    for (const CellIndex& c : cell_) start_blocked_[grid_.index(c[0], c[1])] = 1;
  }
  if (static_cast<int64_t>(cell_.size()) >= options_.parallel_min_robots && kMutant != 6)
    plan_grouped();
  else
    plan_sequential();
}

void Environment::prefetch_window(CellIndex c) const {
  if (sc_.params.s_range > kPrefetchRangeMax) return;
  const exploration::Window w = exploration::window_around(c, sc_.params.s_range, sc_.map_size);
  for (int32_t i = w.i_lo; i <= w.i_hi; ++i)
    grid_.prefetch(grid_.index(i, w.j_lo), static_cast<std::size_t>(w.j_hi - w.j_lo + 1));
}

void Environment::plan_sequential() {
  WindowScratch w;
  const std::size_t n = cell_.size();
  for (std::size_t r = 0; r < std::min(n, kPrefetchAhead); ++r) prefetch_window(cell_[r]);
  for (std::size_t r = 0; r < n; ++r) {
    if (r + kPrefetchAhead < n) prefetch_window(cell_[r + kPrefetchAhead]);
    visited_ += plan_robot(static_cast<int32_t>(r), w);
  }
}

// The candidates of a robot in c: its window without c, raster order, current pheromone.
void Environment::gather(CellIndex c, WindowScratch& w) const {
  w.cell.clear();
  w.at.clear();
  w.tau.clear();
  w.blocked.clear();
  exploration::Window win = exploration::window_around(c, sc_.params.s_range, sc_.map_size);
  if constexpr (kMutant == 2)
    if (win.i_hi == c[0] + sc_.params.s_range) --win.i_hi;   // fault: upper edge one short
  for (int32_t i = win.i_lo; i <= win.i_hi; ++i)
    for (int32_t j = win.j_lo; j <= win.j_hi; ++j) {
      if (i == c[0] && j == c[1]) continue;
      const std::size_t k = grid_.index(i, j);
      w.cell.push_back(k);
      w.at.push_back(CellIndex{i, j});
      w.tau.push_back(grid_.current(k, clock_));
      const bool blocked = kMutant == 6 ? (grid_.obstacle(k) || start_blocked_[k]) : grid_.blocked(k);
      w.blocked.push_back(blocked ? 1 : 0);
    }
}

namespace {
// The tie rule: the last of equal minima (<=); mutant 3 takes the first (<).
inline bool improves(double candidate, double best) {
  if constexpr (kMutant == 3) return candidate < best;
  return candidate <= best;
}
}  // namespace

int32_t Environment::choose_thesis(WindowScratch& w) const {
  const std::size_t n = w.tau.size();
  double sum = 0.0;
  std::vector<double>& prob_n = w.key;
  prob_n.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    prob_n[k] = key(w.tau[k]) * eta_term_;
    sum += prob_n[k];
  }
  double best_value = thesis_best_start_ / sum;
  int32_t best = -1;
  for (std::size_t k = 0; k < n; ++k) {
    const double prob = prob_n[k] / sum;
    if (improves(prob, best_value)) {
      best_value = prob;
      best = static_cast<int32_t>(k);
    }
  }
  return best < 0 ? static_cast<int32_t>(n) - 1 : best;
}

int32_t Environment::choose_deterministic(const WindowScratch& w) const {
  int32_t best = 0;
  double best_key = key(w.tau[0]);
  for (std::size_t k = 1; k < w.tau.size(); ++k) {
    const double kk = key(w.tau[k]);
    if (improves(kk, best_key)) {
      best_key = kk;
      best = static_cast<int32_t>(k);
    }
  }
  return best;
}

int32_t Environment::choose_stochastic(int32_t r, WindowScratch& w) const {
  std::vector<double>& keys = w.key;
  keys.resize(w.tau.size());
  double min_key = keys[0] = key(w.tau[0]);
  for (std::size_t k = 1; k < w.tau.size(); ++k) {
    keys[k] = key(w.tau[k]);
    min_key = std::fmin(min_key, keys[k]);
  }
  uint32_t ties = 0;
  for (double k : keys) ties += k == min_key ? 1U : 0U;
  const uint64_t draw = exploration::rng_key(sc_.seed, tick_, r, exploration::Purpose::tie_break);
  uint32_t pick = exploration::uniform_index(draw, ties);
  for (std::size_t k = 0; k < keys.size(); ++k)
    if (keys[k] == min_key && pick-- == 0) return static_cast<int32_t>(k);
  SWARM_DEMAND(false);
  return -1;
}

// The free candidate a blocked best falls back to, or -1 (stay).
int32_t Environment::substitute(int32_t r, const WindowScratch& w) const {
  if (sc_.rule != RuleSet::stochastic) {
    for (std::size_t k = 0; k < w.blocked.size(); ++k)
      if (!w.blocked[k]) return static_cast<int32_t>(k);
    return -1;
  }
  uint32_t n_free = 0;
  for (uint8_t b : w.blocked) n_free += b ? 0U : 1U;
  if (n_free == 0) return -1;
  const uint64_t draw = exploration::rng_key(sc_.seed, tick_, r, exploration::Purpose::fallback);
  uint32_t pick = exploration::uniform_index(draw, n_free);
  for (std::size_t k = 0; k < w.blocked.size(); ++k)
    if (!w.blocked[k] && pick-- == 0) return static_cast<int32_t>(k);
  SWARM_DEMAND(false);
  return -1;
}

int64_t Environment::plan_robot(int32_t r, WindowScratch& w) {
  const auto ru = static_cast<std::size_t>(r);
  const CellIndex cur = cell_[ru];
  gather(cur, w);
  if (w.tau.empty()) {   // no candidate (a 1 x 1 map): stay
    deposit_centre_[ru] = cur;
    return 0;
  }
  const int32_t best = sc_.rule == RuleSet::thesis          ? choose_thesis(w)
                       : sc_.rule == RuleSet::deterministic ? choose_deterministic(w)
                                                            : choose_stochastic(r, w);
  const auto bu = static_cast<std::size_t>(best);
  const bool best_blocked = w.blocked[bu] != 0;
  const int32_t sub = best_blocked ? substitute(r, w) : -1;
  int64_t newly = 0;
  if (!best_blocked) {
    newly = move(r, w.at[bu], true);
  } else if (sub >= 0) {
    // thesis: the fallback moved a copy, so the new cell is neither occupied nor visited.
    newly = move(r, w.at[static_cast<std::size_t>(sub)], sc_.rule != RuleSet::thesis);
  } else if (sc_.rule == RuleSet::thesis) {
    newly = grid_.mark_visited(w.cell[bu]) ? 1 : 0;   // thesis: the blocked best is "visited"
  }
  const bool centre_is_best = sc_.rule == RuleSet::thesis || kMutant == 1;
  deposit_centre_[ru] = centre_is_best ? w.at[bu] : cell_[ru];
  return newly;
}

int64_t Environment::move(int32_t r, CellIndex to, bool mark) {
  const auto ru = static_cast<std::size_t>(r);
  grid_.set_occupant(grid_.index(cell_[ru][0], cell_[ru][1]), -1);
  cell_[ru] = to;
  waypoint_[ru] = exploration::centre_of(to, sc_.cell_size);
  if (!mark) return 0;
  const std::size_t k = grid_.index(to[0], to[1]);
  SWARM_ASSERT(!grid_.obstacle(k));
  grid_.set_occupant(k, r);
  return grid_.mark_visited(k) ? 1 : 0;
}

double Environment::deposit_amount(int32_t di, int32_t dj) const {
  if (deposit_table_.empty()) return exploration::deposit_amount(sc_.params, di, dj);
  const int32_t side = 2 * deposit_radius_ + 1;
  return deposit_table_[static_cast<std::size_t>((di + deposit_radius_) * side + (dj + deposit_radius_))];
}

void Environment::deposit_around(CellIndex centre) {
  const exploration::Window w = exploration::window_around(centre, sc_.params.s_range, sc_.map_size);
  for (int32_t i = w.i_lo; i <= w.i_hi; ++i)
    for (int32_t j = w.j_lo; j <= w.j_hi; ++j) {
      const std::size_t k = grid_.index(i, j);
      const double amount = deposit_amount(i - centre[0], j - centre[1]);
      grid_.deposit(k, clock_, amount);
    }
}

void Environment::update_progress() {
  if (completion_step_) return;
  eP_ = exploration::exploration_percent(visited_, free_cells_);
  sTime_ = static_cast<double>(tick_) * sc_.params.step_size;
  if (eP_ >= 100.0) completion_step_ = tick_;
}

}  // namespace swarmcheck::impl
