#include "model/exploration/environment_model.hpp"

#include "spec/exploration/choice.hpp"
#include "spec/exploration/handshake.hpp"
#include "spec/exploration/neighbourhood.hpp"
#include "spec/exploration/rng.hpp"
#include "spec/exploration/scenario.hpp"
#include "spec/exploration/trace.hpp"
#include "spec/util/demand.hpp"

namespace swarmcheck::exploration::model {

EnvironmentModel::EnvironmentModel(const Scenario& s)
    : sc_(s),
      n_(s.map_size),
      ertu_dt_(s.params.ertu * s.params.step_size),
      decay_(make_decay_table(evaporation_factor(s.params))),
      handshake_(initial_handshake()) {
  const auto cells = static_cast<Eigen::Index>(int64_t{n_} * n_);
  value_ = Eigen::ArrayXd::Zero(cells);
  written_ = Eigen::Array<int64_t, Eigen::Dynamic, 1>::Zero(cells);
  current_ = Eigen::ArrayXd::Zero(cells);
  visited_flag_ = Eigen::Array<bool, Eigen::Dynamic, 1>::Constant(cells, false);
  obstacle_ = Eigen::Array<bool, Eigen::Dynamic, 1>::Constant(cells, false);
  occupant_ = Eigen::ArrayXi::Constant(cells, -1);
  // Thesis setEnvironment order: robots deposit and mark their cells, then obstacles are set.
  for (std::size_t r = 0; r < s.robots.size(); ++r) {
    const CellIndex c = cell_of(s.robots[r], s.cell_size);
    robots_.push_back(EnvRobot{c, s.robots[r]});
    deposit_around(c);
    occupant_[static_cast<Eigen::Index>(index(c))] = static_cast<int>(r);
    visited_flag_[static_cast<Eigen::Index>(index(c))] = true;
  }
  for (const CellIndex& c : s.obstacles) obstacle_[static_cast<Eigen::Index>(index(c))] = true;
  free_cells_ = free_cell_count(s);
  deposit_centre_.resize(robots_.size());
  visited_ = visited_flag_.count();
  update_progress();
  SWARM_DEMAND(free_cells_ >= static_cast<int64_t>(robots_.size()));
}

std::size_t EnvironmentModel::index(CellIndex c) const {
  SWARM_DEMAND(in_map(c, n_));
  return static_cast<std::size_t>(c[0]) * static_cast<std::size_t>(n_) +
         static_cast<std::size_t>(c[1]);
}

Cell EnvironmentModel::cell(CellIndex c) const {
  const auto k = static_cast<Eigen::Index>(index(c));
  return Cell{current_[k], tick_, visited_flag_[k], obstacle_[k], occupant_[k]};
}

uint64_t EnvironmentModel::pheromone_digest() const {
  Fnv1a h;
  for (Eigen::Index k = 0; k < current_.size(); ++k) h.add(current_[k]);
  return h.h;
}

void EnvironmentModel::step(bool all_arrived) {
  bool planning = true;
  if (sc_.mode == Mode::cosim) {
    const HandshakeStep hs = environment_handshake(handshake_, all_arrived);
    planning = hs.plan;
    handshake_ = hs.next;
  }
  if (planning) plan();
  evaporate();
  if (planning) {
    for (const CellIndex& c : deposit_centre_) deposit_around(c);
    ++planning_steps_;
  }
  update_progress();
}

void EnvironmentModel::plan() {
  for (int32_t r = 0; r < static_cast<int32_t>(robots_.size()); ++r) {
    if (sc_.rule == RuleSet::thesis)
      plan_robot_thesis(r);
    else
      plan_robot(r);
  }
  if (sc_.rule == RuleSet::thesis) visited_ = visited_flag_.count();
}

namespace {

std::vector<Candidate> candidates_of(CellIndex c, const Scenario& s, const Eigen::ArrayXd& tau,
                                     const Eigen::Array<bool, Eigen::Dynamic, 1>& obstacle,
                                     const Eigen::ArrayXi& occupant) {
  std::vector<Candidate> out;
  const Window w = window_around(c, s.params.s_range, s.map_size);
  for (int32_t i = w.i_lo; i <= w.i_hi; ++i)
    for (int32_t j = w.j_lo; j <= w.j_hi; ++j) {
      if (i == c[0] && j == c[1]) continue;
      const auto k = static_cast<Eigen::Index>(int64_t{i} * s.map_size + j);
      out.push_back(Candidate{CellIndex{i, j}, tau[k], obstacle[k] || occupant[k] >= 0});
    }
  return out;
}

}  // namespace

// Fixed rule sets: move to the target (marking it occupied and visited); deposit where it is.
void EnvironmentModel::plan_robot(int32_t r) {
  EnvRobot& robot = robots_[static_cast<std::size_t>(r)];
  const auto cands = candidates_of(robot.cell, sc_, current_, obstacle_, occupant_);
  const Choice ch =
      sc_.rule == RuleSet::deterministic
          ? choose_deterministic(cands, sc_.params)
          : choose_stochastic(cands, sc_.params,
                              rng_key(sc_.seed, tick_, r, Purpose::tie_break),
                              rng_key(sc_.seed, tick_, r, Purpose::fallback));
  if (ch.target >= 0) move_robot(r, cands[static_cast<std::size_t>(ch.target)].cell, true);
  deposit_centre_[static_cast<std::size_t>(r)] = robot.cell;
}

// The thesis's move(), bugs included: the fallback moves a copy (the new cell is neither
// occupied nor visited on the map); a blocked best with no free cell marks that best visited;
// the deposit goes around the chosen best, not where the robot went.
void EnvironmentModel::plan_robot_thesis(int32_t r) {
  EnvRobot& robot = robots_[static_cast<std::size_t>(r)];
  const auto cands = candidates_of(robot.cell, sc_, current_, obstacle_, occupant_);
  const Choice ch = choose_thesis(cands, sc_.params);
  if (ch.best < 0) {   // no candidate at all (a 1x1 map): stay
    deposit_centre_[static_cast<std::size_t>(r)] = robot.cell;
    return;
  }
  const CellIndex best = cands[static_cast<std::size_t>(ch.best)].cell;
  if (ch.target >= 0 && !ch.fallback) {
    move_robot(r, best, true);
  } else if (ch.fallback) {
    move_robot(r, cands[static_cast<std::size_t>(ch.target)].cell, false);
  } else {
    visited_flag_[static_cast<Eigen::Index>(index(best))] = true;
  }
  deposit_centre_[static_cast<std::size_t>(r)] = best;
}

void EnvironmentModel::move_robot(int32_t r, CellIndex to, bool mark) {
  EnvRobot& robot = robots_[static_cast<std::size_t>(r)];
  occupant_[static_cast<Eigen::Index>(index(robot.cell))] = -1;
  robot.cell = to;
  robot.waypoint = centre_of(to, sc_.cell_size);
  if (!mark) return;
  const auto k = static_cast<Eigen::Index>(index(to));
  SWARM_DEMAND(!obstacle_[k]);
  occupant_[k] = r;
  if (!visited_flag_[k]) {
    visited_flag_[k] = true;
    ++visited_;
  }
}

void EnvironmentModel::evaporate() {
  ++tick_;
  for (Eigen::Index k = 0; k < current_.size(); ++k) {
    if (sc_.rule == RuleSet::thesis) {
      current_[k] = thesis_evaporate(current_[k], ertu_dt_);
      value_[k] = current_[k];
      written_[k] = tick_;
    } else {
      current_[k] = value_[k] * decay_factor(decay_, tick_ - written_[k]);
    }
  }
}

void EnvironmentModel::deposit_around(CellIndex centre) {
  const Window w = window_around(centre, sc_.params.s_range, n_);
  for (int32_t i = w.i_lo; i <= w.i_hi; ++i)
    for (int32_t j = w.j_lo; j <= w.j_hi; ++j) {
      const auto k = static_cast<Eigen::Index>(index(CellIndex{i, j}));
      current_[k] = current_[k] + deposit_amount(sc_.params, i - centre[0], j - centre[1]);
      value_[k] = current_[k];
      written_[k] = tick_;
    }
}

void EnvironmentModel::update_progress() {
  if (completion_step_) return;   // eP and sTime are frozen once exploration is complete
  eP_ = exploration_percent(visited_, free_cells_);
  sTime_ = static_cast<double>(tick_) * sc_.params.step_size;
  if (eP_ >= 100.0) completion_step_ = tick_;
}

}  // namespace swarmcheck::exploration::model
