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
#include <type_traits>
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
  using Domain = num::Concrete;  // the generic stages below read their domain from the config
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

// ---- The stages, written once over the config's domain (Cfg::Domain, spec/util/num.hpp).
// model/ and impl/ run them on EnvironmentConfig, EnvironmentState and their grids; proofs/
// interprets the same templates on symbolic ones (a symbolic map, symbolic robot cells), so that
// an obligation about the step reads these functions, not a restatement of them. A condition on
// a symbolic value is a num::when or num::branch; an effect on the grid under such a condition
// runs on a copy that is merged back (a symbolic grid is a list of guarded writes).

// How many cells a stage newly marked visited.
template <class D>
using CountOf = std::conditional_t<num::is_concrete<D>, int64_t, sym::Int>;

// A window cell's candidate: a concrete one is in the window by construction; a symbolic one is
// present when its cell is in the window (and marked as gathered here).
inline void gathered(Candidate&, bool) {}
inline void gathered(SymbolicCandidate& c, const sym::Bool& in_window) {
  constexpr const char* fn = "exploration::gather_candidates";
  c.present = num::traced(fn, c.present && in_window);
  c.tau = num::traced(fn, c.tau);
  c.blocked = num::traced(fn, c.blocked);
}

// The candidates of a robot in c: its window without c, raster order, pheromone at tick. (Any
// allocator: impl's per-thread buffers keep to their own cache lines.) A grid that gathers a
// window itself (impl's LazyGrid, row by row, `gather_window`) must give exactly this list; the
// conformance harness holds it to that.
template <class Cfg, class G, class Cell, class Vec>
void gather_candidates(const Cfg& cfg, const G& grid, const Cell& c, int64_t tick, Vec& out) {
  if constexpr (requires { grid.gather_window(cfg, c, tick, out); }) {
    grid.gather_window(cfg, c, tick, out);
    return;
  }
  out.clear();
  const int32_t s_range = cfg.scenario.params.s_range;
  const auto w = window_around(c, s_range, cfg.scenario.map_size);
  for_each_window_cell(w, c, s_range, [&](const auto& cell, const auto& in_window, int32_t di, int32_t dj) {
    if (di == 0 && dj == 0) return;   // the robot's own cell
    auto candidate = grid.candidate(cell, tick);
    gathered(candidate, in_window);
    out.push_back(candidate);
  });
}

// A decision's effect on the grid (the old cell released, the new one occupied, a cell marked
// visited); returns how many cells it newly marked visited (0 or 1). `from` is the robot's cell.
template <class G, class Cell, class Decision>
auto apply_decision_to_grid(G& grid, const Cell& from, int32_t r, const Decision& d) {
  using Count = std::conditional_t<std::is_same_v<std::decay_t<decltype(d.moves)>, bool>, int64_t, sym::Int>;
  constexpr const char* fn = "exploration::apply_decision_to_grid";
  num::when(num::traced(fn, d.moves), grid, [&](G& g) {
    g.release(from);
    num::when(num::traced(fn, d.occupies), g, [&](G& occupied) { occupied.occupy(d.to, r); });
  });
  return num::when_else(
      num::traced(fn, d.marks), grid,
      [&](G& g) { return num::select(g.mark_visited(d.mark), Count(1), Count(0)); }, Count(0));
}

// A decision's effect on the robot's record: its cell, waypoint and deposit centre. Nothing
// another robot's decision reads (they read the grid), so it may wait until the stage's end.
template <class Cfg, class Env, class Decision>
void apply_decision_to_robot(const Cfg& cfg, Env& env, int32_t r, const Decision& d) {
  using D = typename Cfg::Domain;
  num::when(num::traced("exploration::apply_decision_to_robot", d.moves), env.robots[static_cast<std::size_t>(r)],
            [&](auto& robot) {
    robot.cell = d.to;
    robot.waypoint = centre_of_rule<D>(d.to, cfg.scenario.cell_size);
  });
  env.deposit_centre[static_cast<std::size_t>(r)] = d.deposit_centre;
}

// One robot's decision on the grid: gather, choose, decide, and the decision's grid effects.
// `newly` counts the cells it newly marked visited. `scratch` is reused storage.
template <class Cfg, class Env, class G, class Vec, class Count>
auto decide_on_grid(const Cfg& cfg, const Env& env, G& grid, int32_t r, Vec& scratch, Count& newly) {
  using D = typename Cfg::Domain;
  if constexpr (num::is_concrete<D>) static_assert(EnvironmentGrid<G>);
  const auto current = env.robots[static_cast<std::size_t>(r)].cell;
  gather_candidates(cfg, grid, current, env.tick, scratch);
  const std::span<const CandidateOf<D>> candidates(scratch.data(), scratch.size());
  const auto ch = choose(*cfg.rules, cfg.terms, candidates, draw_site<D>(cfg.scenario.seed, env.tick, r));
  const auto d = decide(*cfg.rules, current, candidates, ch);
  newly = newly + apply_decision_to_grid(grid, current, r, d);
  return d;
}

// One robot's planning step: its decision on the grid, then on its record. Returns how many cells
// it newly marked visited.
template <class Cfg, class Env, class G, class Vec>
CountOf<typename Cfg::Domain> plan_robot(const Cfg& cfg, Env& env, G& grid, int32_t r, Vec& scratch) {
  CountOf<typename Cfg::Domain> newly(0);
  apply_decision_to_robot(cfg, env, r, decide_on_grid(cfg, env, grid, r, scratch, newly));
  return newly;
}

// The deposit of one robot around `centre`, window cells in raster order.
template <class Cfg, class G, class Cell>
void deposit_around(const Cfg& cfg, G& grid, const Cell& centre, int64_t tick) {
  const int32_t s_range = cfg.scenario.params.s_range;
  const auto w = window_around(centre, s_range, cfg.scenario.map_size);
  for_each_window_cell(w, centre, s_range, [&](const auto& cell, const auto& in_window, int32_t di, int32_t dj) {
    num::when(in_window, grid, [&](G& g) {
      g.deposit(cell, tick, num::traced("exploration::deposit_around", cfg.deposit.amount(di, dj)));
    });
  });
}

// The spec's stages: robots one after another in index order. Any other Stages (parallel
// groups, prefetching) must give exactly these results.
struct IndexOrder {
  template <class Cfg, class Env, class G>
  CountOf<typename Cfg::Domain> plan(const Cfg& cfg, Env& env, G& grid) const {
    using D = typename Cfg::Domain;
    std::vector<CandidateOf<D>> scratch;
    CountOf<D> newly(0);
    for (std::size_t r = 0; r < env.robots.size(); ++r)
      newly = newly + plan_robot(cfg, env, grid, static_cast<int32_t>(r), scratch);
    return newly;
  }
  template <class Cfg, class Env, class G>
  void deposit(const Cfg& cfg, const Env& env, G& grid) const {
    for (const auto& c : env.deposit_centre) deposit_around(cfg, grid, c, env.tick);
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
template <class Cfg, class Env, class G, class Stages = IndexOrder>
void environment_stages(const Cfg& cfg, Env& env, G& grid, bool planning, const Stages& stages = Stages{}) {
  if (planning) env.progress.visited = env.progress.visited + stages.plan(cfg, env, grid);
  ++env.tick;
  grid.evaporate(env.tick);
  if (planning) {
    stages.deposit(cfg, env, grid);
    ++env.planning_steps;
  }
  update_progress(env.progress, env.tick, cfg.scenario.params.step_size);
}

// One Environment step (the stages above). all_arrived is ignored in abstract mode.
template <class Cfg, class Env, class G, class Stages = IndexOrder>
void environment_step(const Cfg& cfg, Env& env, G& grid, bool all_arrived, const Stages& stages = Stages{}) {
  environment_stages(cfg, env, grid, handshake_stage(cfg.scenario.mode, env.handshake, all_arrived), stages);
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
