#pragma once
// @component Environment (thesis Environment FMU), the executable small step (spec/SPEC.md
// section 6). Written once, here; model/ runs it on a dense grid that evaluates every cell every
// step, impl/ on a lazy grid and, for many robots, with planning by independent groups.
//   inputs:  all_arrived (AND of the controllers' onDestinationOutput, previous step; cosim)
//   state:   EnvironmentState (plain values) + a grid (pheromone, visited, obstacle, occupant)
//   outputs: each robot's waypoint, onDestinationOutput, eP, sTime
//   no direct feedthrough.
//
// Like mjModel / mjData: EnvironmentConfig is constant for a run, EnvironmentState is what a
// step changes. One step at tick t, as named stages:
//   1. handshake: plan = abstract ? true : environment_handshake(state, all_arrived).plan
//   2. plan:      robots choose from the pheromone at t and move (Stages::plan: index order, or
//                 anything with the same result); each fixes its deposit centre
//   3. evaporate: tick := t + 1; every cell evaporates by one step (decay function or literal)
//   4. deposit:   robot by robot in index order, around the deposit centres (Stages::deposit)
//   5. progress:  eP, sTime; frozen from the first step with eP >= 100
//
// The grid is anything with these operations (a cell's pheromone is as of the tick given):
//   Candidate candidate(CellIndex c, int64_t tick) const   {c, pheromone, obstacle or occupied}
//   double    pheromone(CellIndex c, int64_t tick) const
//   void      release(CellIndex c)               no robot stands on c (unconditionally)
//   void      occupy(CellIndex c, int32_t r)     robot r stands on c (never an obstacle)
//   bool      mark_visited(CellIndex c)          true if c was not visited before
//   void      set_obstacle(CellIndex c)
//   void      evaporate(int64_t tick)            every cell from tick - 1 to tick
//   void      deposit(CellIndex c, int64_t tick, double amount)   value at tick + amount
#include <concepts>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "spec/exploration/choice.hpp"
#include "spec/exploration/decay.hpp"
#include "spec/exploration/deposit.hpp"
#include "spec/exploration/handshake.hpp"
#include "spec/exploration/neighbourhood.hpp"
#include "spec/exploration/rule_set.hpp"
#include "spec/exploration/scenario.hpp"
#include "spec/exploration/trace.hpp"
#include "spec/exploration/types.hpp"

namespace swarmcheck::exploration {

template <class G>
concept EnvironmentGrid = requires(G& g, const G& cg, CellIndex c, int64_t tick, double amount, int32_t r) {
  { cg.candidate(c, tick) } -> std::same_as<Candidate>;
  { cg.pheromone(c, tick) } -> std::same_as<double>;
  g.release(c);
  g.occupy(c, r);
  { g.mark_visited(c) } -> std::same_as<bool>;
  g.set_obstacle(c);
  g.evaporate(tick);
  g.deposit(c, tick, amount);
};

// Constant for a run: the scenario and what is derived from it once.
struct EnvironmentConfig {
  Scenario scenario;
  const RuleDescriptor* rules;   // the row of scenario.rule
  ChoiceTerms terms;
  DepositKernel deposit;
  DecayTable decay;              // P[i] = f^(2^i) of the decay function
  double ertu_dt;                // ertu * step_size, the literal update's one factor
};
EnvironmentConfig make_environment_config(const Scenario& s);   // s must be valid

// Exploration progress (spec/SPEC.md section 6, stage 5).
struct Progress {
  int64_t visited = 0;
  int64_t free_cells = 0;
  double eP = 0;       // percent
  double sTime = 0;    // s
  std::optional<int64_t> completion_step;
};
// eP = visited / free_cells * 100 and sTime = tick * step_size, unless already complete; the run
// completes at the first tick with eP >= 100, and both are frozen from then on.
void update_progress(Progress& p, int64_t tick, double step_size_s);

// Everything a step changes except the grid.
struct EnvironmentState {
  HandshakeState handshake;
  int64_t tick = 0;
  int64_t planning_steps = 0;
  std::vector<EnvRobot> robots;            // cell and waypoint, by robot index
  std::vector<CellIndex> deposit_centre;   // of the last planning step
  Progress progress;
};

// A grid that gathers a window itself (impl's LazyGrid, row by row) must give exactly the list
// below; the conformance harness holds it to that.
template <class G, class Alloc>
concept GathersWindows = requires(const G& g, const EnvironmentConfig& cfg, CellIndex c, int64_t tick,
                                  std::vector<Candidate, Alloc>& out) { g.gather_window(cfg, c, tick, out); };

// The candidates of a robot in c: its window without c, raster order, pheromone at tick. (Any
// allocator: impl's per-thread buffers keep to their own cache lines.)
template <EnvironmentGrid G, class Alloc>
void gather_candidates(const EnvironmentConfig& cfg, const G& grid, CellIndex c, int64_t tick,
                       std::vector<Candidate, Alloc>& out) {
  if constexpr (GathersWindows<G, Alloc>) {
    grid.gather_window(cfg, c, tick, out);
    return;
  }
  out.clear();
  const Window w = window_around(c, cfg.scenario.params.s_range, cfg.scenario.map_size);
  for (int32_t i = w.i_lo; i <= w.i_hi; ++i)
    for (int32_t j = w.j_lo; j <= w.j_hi; ++j)
      if (i != c[0] || j != c[1]) out.push_back(grid.candidate(CellIndex{i, j}, tick));
}

// A decision's effect on the grid (the old cell released, the new one occupied, a cell marked
// visited); returns how many cells it newly marked visited (0 or 1). `from` is the robot's cell.
template <EnvironmentGrid G>
int64_t apply_decision_to_grid(G& grid, CellIndex from, int32_t r, const RobotDecision& d) {
  if (d.moves) {
    grid.release(from);
    if (d.occupies) grid.occupy(d.to, r);
  }
  return d.marks && grid.mark_visited(d.mark) ? 1 : 0;
}

// A decision's effect on the robot's record: its cell, waypoint and deposit centre. Nothing
// another robot's decision reads (they read the grid), so it may wait until the stage's end.
inline void apply_decision_to_robot(const EnvironmentConfig& cfg, EnvironmentState& env, int32_t r,
                                    const RobotDecision& d) {
  if (d.moves) {
    EnvRobot& robot = env.robots[static_cast<std::size_t>(r)];
    robot.cell = d.to;
    robot.waypoint = centre_of(d.to, cfg.scenario.cell_size);
  }
  env.deposit_centre[static_cast<std::size_t>(r)] = d.deposit_centre;
}

// One robot's decision on the grid: gather, choose, decide, and the decision's grid effects.
// `newly` counts the cells it newly marked visited. `scratch` is reused storage.
template <EnvironmentGrid G, class Alloc>
RobotDecision decide_on_grid(const EnvironmentConfig& cfg, const EnvironmentState& env, G& grid, int32_t r,
                             std::vector<Candidate, Alloc>& scratch, int64_t& newly) {
  const CellIndex current = env.robots[static_cast<std::size_t>(r)].cell;
  gather_candidates(cfg, grid, current, env.tick, scratch);
  const Choice ch = choose(*cfg.rules, cfg.terms, scratch, DrawSite{cfg.scenario.seed, env.tick, r});
  const RobotDecision d = decide(*cfg.rules, current, scratch, ch);
  newly += apply_decision_to_grid(grid, current, r, d);
  return d;
}

// One robot's planning step: its decision on the grid, then on its record. Returns how many cells
// it newly marked visited.
template <EnvironmentGrid G>
int64_t plan_robot(const EnvironmentConfig& cfg, EnvironmentState& env, G& grid, int32_t r,
                   std::vector<Candidate>& scratch) {
  int64_t newly = 0;
  apply_decision_to_robot(cfg, env, r, decide_on_grid(cfg, env, grid, r, scratch, newly));
  return newly;
}

// The deposit of one robot around `centre`, window cells in raster order.
template <EnvironmentGrid G>
void deposit_around(const EnvironmentConfig& cfg, G& grid, CellIndex centre, int64_t tick) {
  const Window w = window_around(centre, cfg.scenario.params.s_range, cfg.scenario.map_size);
  for (int32_t i = w.i_lo; i <= w.i_hi; ++i)
    for (int32_t j = w.j_lo; j <= w.j_hi; ++j)
      grid.deposit(CellIndex{i, j}, tick, cfg.deposit.amount(i - centre[0], j - centre[1]));
}

// The spec's stages: robots one after another in index order. Any other Stages (parallel
// groups, prefetching) must give exactly these results.
struct IndexOrder {
  template <EnvironmentGrid G>
  int64_t plan(const EnvironmentConfig& cfg, EnvironmentState& env, G& grid) const {
    std::vector<Candidate> scratch;
    int64_t newly = 0;
    for (std::size_t r = 0; r < env.robots.size(); ++r)
      newly += plan_robot(cfg, env, grid, static_cast<int32_t>(r), scratch);
    return newly;
  }
  template <EnvironmentGrid G>
  void deposit(const EnvironmentConfig& cfg, const EnvironmentState& env, G& grid) const {
    for (const CellIndex& c : env.deposit_centre) deposit_around(cfg, grid, c, env.tick);
  }
};

// Initialisation (thesis setEnvironment): robots in index order deposit around their start cell
// and mark it occupied and visited; then obstacles are set. The deposits touch only pheromone and
// the marks only occupancy, so all deposits go first, as a planning step's deposit stage around
// the start cells (Stages::deposit: index order, or anything with the same result).
template <EnvironmentGrid G, class Stages = IndexOrder>
EnvironmentState initial_environment(const EnvironmentConfig& cfg, G& grid, const Stages& stages = Stages{}) {
  const Scenario& s = cfg.scenario;
  EnvironmentState env;
  env.handshake = initial_handshake();
  env.robots.reserve(s.robots.size());
  env.deposit_centre.reserve(s.robots.size());
  for (const Point_m& p : s.robots) {
    env.robots.push_back(EnvRobot{cell_of(p, s.cell_size), p});
    env.deposit_centre.push_back(env.robots.back().cell);
  }
  stages.deposit(cfg, env, grid);   // at tick 0
  for (std::size_t r = 0; r < env.robots.size(); ++r) {
    grid.occupy(env.robots[r].cell, static_cast<int32_t>(r));
    env.progress.visited += grid.mark_visited(env.robots[r].cell) ? 1 : 0;
  }
  for (const CellIndex& c : s.obstacles) grid.set_obstacle(c);
  env.progress.free_cells = free_cell_count(s);
  update_progress(env.progress, 0, s.params.step_size);
  return env;
}

// Stages 2 to 5 of a step, whether it plans given (the handshake's verdict, or another protocol's:
// the FMI Environment's epoch handshake decides it from its own inputs).
template <EnvironmentGrid G, class Stages = IndexOrder>
void environment_stages(const EnvironmentConfig& cfg, EnvironmentState& env, G& grid, bool planning,
                        const Stages& stages = Stages{}) {
  if (planning) env.progress.visited += stages.plan(cfg, env, grid);
  ++env.tick;
  grid.evaporate(env.tick);
  if (planning) {
    stages.deposit(cfg, env, grid);
    ++env.planning_steps;
  }
  update_progress(env.progress, env.tick, cfg.scenario.params.step_size);
}

// One Environment step (the stages above). all_arrived is ignored in abstract mode.
template <EnvironmentGrid G, class Stages = IndexOrder>
void environment_step(const EnvironmentConfig& cfg, EnvironmentState& env, G& grid, bool all_arrived,
                      const Stages& stages = Stages{}) {
  bool planning = true;
  if (cfg.scenario.mode == Mode::cosim) {
    const HandshakeStep hs = environment_handshake(env.handshake, all_arrived);
    planning = hs.plan;
    env.handshake = hs.next;
  }
  environment_stages(cfg, env, grid, planning, stages);
}

// FNV-1a over the bits of every cell's pheromone at tick, raster order.
template <EnvironmentGrid G>
uint64_t pheromone_digest(const EnvironmentConfig& cfg, const G& grid, int64_t tick) {
  Fnv1a h;
  const int32_t n = cfg.scenario.map_size;
  for (int32_t i = 0; i < n; ++i)
    for (int32_t j = 0; j < n; ++j) h.add(grid.pheromone(CellIndex{i, j}, tick));
  return h.h;
}

}  // namespace swarmcheck::exploration
