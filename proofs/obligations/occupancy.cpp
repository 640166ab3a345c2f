// Obligation occupancy: one planning step of the fixed rule sets keeps every robot in the map,
// off obstacles, and the grid naming it as its cell's occupant (so no two robots share a cell),
// for every number of robots. The step is the spec's own IndexOrder::plan and everything under
// it, interpreted on a symbolic world (symbolic_world.hpp); the parts are in occupancy.hpp.
#include "proofs/obligations/occupancy.hpp"

#include <array>
#include <fmt/format.h>

#include "proofs/obligations/obligation.hpp"
#include "proofs/obligations/replay_grid.hpp"
#include "proofs/obligations/symbolic_world.hpp"
#include "spec/exploration/environment_step.hpp"
#include "spec/exploration/scenario.hpp"

namespace swarmcheck::proofs {
namespace occupancy {

constexpr unsigned kIndexBits = 8;   // window indices and counts: s_range <= 3 has 48 candidates

std::vector<exploration::SymbolicCandidate> symbolic_window(int s_range, const std::string& prefix) {
  std::vector<exploration::SymbolicCandidate> out;
  const int side = 2 * s_range + 1;
  for (int k = 0; k < side * side - 1; ++k)
    out.push_back({{sym::Int(0), sym::Int(k)},
                   sym::Real::var(fmt::format("{}_tau_{}", prefix, k)),
                   sym::Bool::var(fmt::format("{}_blocked_{}", prefix, k)),
                   sym::Bool::var(fmt::format("{}_present_{}", prefix, k))});
  return out;
}

ChoiceQuery choice_query(Translator& t, const exploration::RuleDescriptor& rules,
                         const std::vector<exploration::SymbolicCandidate>& cands, bool free_target) {
  z3::context& c = t.ctx();
  // phi = 1: a key is the pheromone, already any real (pow of a free value adds nothing).
  const exploration::ChoiceTermsT<num::Symbolic> terms{sym::Real(1.0), sym::Real::var("eta_term"),
                                                       sym::Real::var("thesis_best_start")};
  const exploration::ChoiceT<num::Symbolic> ch =
      exploration::choose(rules, terms, cands, exploration::SymbolicDrawSite{"robot"});
  const z3::expr target = t(ch.target), best = t(ch.best);
  z3::expr ok = target == c.bv_val(-1, kIndexBits), best_ok = best == c.bv_val(-1, kIndexBits);
  for (std::size_t k = 0; k < cands.size(); ++k) {
    const z3::expr at = c.bv_val(static_cast<int>(k), kIndexBits);
    ok = ok || (target == at && t(cands[k].present) && (free_target ? !t(cands[k].blocked) : c.bool_val(true)));
    best_ok = best_ok || (best == at && t(cands[k].present));
  }
  return {target, free_target ? !ok : !(ok && best_ok)};
}

}  // namespace occupancy

namespace {

using S = num::Symbolic;
using world::Cell;
constexpr int kMaxRange = 3;

constexpr std::array<exploration::RuleSet, 2> kRuleSets{exploration::RuleSet::deterministic,
                                                        exploration::RuleSet::stochastic};

struct Check {
  z3::check_result result;
  std::string detail;
};

// Replays a choice counterexample through the executed choose(): the model's present
// candidates, in order. The stochastic rules draw from seeds 0..999 (the model's draws are free
// choices): confirmed when one seed sends the robot to a blocked candidate (free_target), or
// names an index outside the list.
bool replay_choice(const z3::model& m, Translator& t, const exploration::RuleDescriptor& rules,
                   const std::vector<exploration::SymbolicCandidate>& cands, bool free_target, std::string& detail) {
  std::vector<exploration::Candidate> concrete;
  std::vector<std::size_t> slot;
  for (std::size_t k = 0; k < cands.size(); ++k) {
    if (!m.eval(t(cands[k].present), true).is_true()) continue;
    concrete.push_back({{0, static_cast<int32_t>(k)}, model_double(m, t(cands[k].tau)),
                        m.eval(t(cands[k].blocked), true).is_true()});
    slot.push_back(k);
  }
  const exploration::ChoiceTerms terms{1.0, model_double(m, m.ctx().real_const("eta_term")),
                                       model_double(m, m.ctx().real_const("thesis_best_start"))};
  const bool draws = rules.best == exploration::BestRule::uniform_minimum ||
                     rules.fallback == exploration::FallbackRule::uniform_free;
  const auto n = static_cast<int32_t>(concrete.size());
  for (uint64_t seed = 0; seed < (draws ? 1000U : 1U); ++seed) {
    const exploration::Choice ch = exploration::choose(rules, terms, concrete, exploration::DrawSite{seed, 0, 0});
    std::string wrong;
    if (ch.target >= n || ch.target < -1 || ch.best >= n || ch.best < -1 || (n > 0 && ch.best < 0))
      wrong = fmt::format("names index {} / {} of a list of {}", ch.best, ch.target, n);
    else if (free_target && ch.target >= 0 && concrete[static_cast<std::size_t>(ch.target)].blocked)
      wrong = fmt::format("sends the robot to candidate {} of the window, which is blocked",
                          slot[static_cast<std::size_t>(ch.target)]);
    if (wrong.empty()) continue;
    std::size_t blocked = 0;
    for (const auto& x : concrete) blocked += x.blocked ? 1 : 0;
    detail = fmt::format("{} candidates ({} blocked): choose() {} (seed {}; confirmed by running choose())",
                         concrete.size(), blocked, wrong, seed);
    return true;
  }
  return false;
}

}  // namespace

namespace occupancy {

std::optional<Outcome> choice_lemma(Session& session, exploration::RuleSet set, int s_range, bool free_target) {
  const exploration::RuleDescriptor& rules = exploration::rules_of(set);
  Translator t(session, RealTheory::real, false, occupancy::kIndexBits);
  const auto cands = occupancy::symbolic_window(s_range, "c");
  const occupancy::ChoiceQuery q = occupancy::choice_query(t, rules, cands, free_target);
  z3::solver s = session.make_preprocessed_solver();
  s.add(t.side_conditions());
  // The thesis rule divides by the sum of the keys: over the reals it is positive (IEEE gives inf
  // and NaN at 0, which the concrete rule resolves as "every candidate tied").
  if (rules.best == exploration::BestRule::thesis_normalised)
    for (const auto& c : cands) s.add(t(c.tau) > 0);
  s.add(q.violates);
  const std::string label = fmt::format("choice-{}-{}-s{}", free_target ? "free" : "present", rules.name, s_range);
  const z3::check_result r = session.check_preprocessed(s, label);
  if (r == z3::unsat) return std::nullopt;
  if (r != z3::sat) return Outcome{Verdict::unknown, "unknown on query " + label, {}};
  std::string detail;
  const bool confirmed = replay_choice(s.get_model(), t, rules, cands, free_target, detail);
  return Outcome{confirmed ? Verdict::refuted : Verdict::unknown,
                 "sat: " + label + ": " +
                     (confirmed ? detail : "NOT reproduced by the executed choose(): a spurious counterexample"),
                 {}};
}

}  // namespace occupancy

namespace {

// The occupancy invariant of robot k: in the map, off obstacles, the grid's occupant of its cell.
sym::Bool robot_ok(const world::Config& cfg, const world::Environment& env, const world::Grid& grid, int k) {
  const Cell& p = env.robots[static_cast<std::size_t>(k)].cell;
  return exploration::in_map_rule<S>(p, cfg.scenario.map_size) && !grid.obstacle(p) && grid.occupant(p) == k;
}

// The world of a planning step: robots at free cells of a symbolic map of any contents, the
// pheromone written at this tick (any value: the choice lemma holds for any).
struct StepWorld {
  world::Config cfg;
  world::Environment env;
  world::Grid grid;
  StepWorld(exploration::RuleSet set, int s_range, int robots, world::ChoiceMode choice = world::ChoiceMode::exact)
      : cfg(world::symbolic_config(set, s_range, choice)), env(world::symbolic_environment(cfg, robots, "robot", 1)),
        grid(cfg, "map", 1, 1) {}
};

// Runs the spec's planning stage on the world: every robot in index order (IndexOrder::plan), or
// only robot 0 (plan_robot: one pass of the robots' loop).
void plan(StepWorld& w, bool one_mover) {
  if (one_mover) {
    std::vector<exploration::SymbolicCandidate> scratch;
    exploration::plan_robot(w.cfg, w.env, w.grid, 0, scratch);
  } else {
    exploration::IndexOrder{}.plan(w.cfg, w.env, w.grid);
  }
}

// Replays a counterexample's state through the executed code: IndexOrder::plan on a concrete
// config and a ReplayGrid holding the model's map around the robots (the stochastic rules with
// seeds 0..999). Confirmed when the concrete step breaks the invariant.
bool replay_step(const z3::model& m, Translator& t, const StepWorld& before, exploration::RuleSet set, int s_range,
                 std::string& detail) {
  auto integer = [&](const sym::Int& x) { return static_cast<int32_t>(m.eval(t(x), true).get_numeral_int64()); };
  auto flag = [&](const sym::Bool& x) { return m.eval(t(x), true).is_true(); };
  exploration::Scenario sc = exploration::default_scenario();
  sc.map_size = integer(before.cfg.scenario.map_size);
  sc.rule = set;
  sc.params.s_range = s_range;
  sc.params.phi = 1.0;
  sc.obstacles.clear();
  const std::size_t n = before.env.robots.size();
  exploration::EnvironmentConfig cfg = exploration::make_environment_config(sc);
  exploration::EnvironmentState env0;
  env0.handshake = exploration::initial_handshake();
  env0.tick = before.env.tick;
  std::vector<exploration::CellIndex> cells;
  for (std::size_t k = 0; k < n; ++k) {
    const exploration::CellIndex c{integer(before.env.robots[k].cell[0]), integer(before.env.robots[k].cell[1])};
    cells.push_back(c);
    env0.robots.push_back({c, exploration::centre_of(c, sc.cell_size)});
    env0.deposit_centre.push_back(c);
  }
  ReplayGrid grid0(cfg, before.env.tick);
  for (const exploration::CellIndex& c : cells)
    for (int32_t di = -s_range; di <= s_range; ++di)
      for (int32_t dj = -s_range; dj <= s_range; ++dj) {
        const exploration::CellIndex x{c[0] + di, c[1] + dj};
        const Cell sx{sym::Int(x[0]), sym::Int(x[1])};
        ReplayGrid::Content& content = grid0.at(x);
        content.obstacle = flag(before.grid.obstacle(sx));
        content.occupant = integer(before.grid.occupant(sx));
        content.visited = flag(before.grid.visited(sx));
        content.value = model_double(m, t(before.grid.stored(sx)));
        content.written = before.env.tick;
      }
  const bool draws = set == exploration::RuleSet::stochastic;
  for (uint64_t seed = 0; seed < (draws ? 1000U : 1U); ++seed) {
    cfg.scenario.seed = seed;
    exploration::EnvironmentState env = env0;
    ReplayGrid grid = grid0;
    exploration::IndexOrder{}.plan(cfg, env, grid);
    for (std::size_t k = 0; k < n; ++k) {
      const exploration::CellIndex c = env.robots[k].cell;
      std::string broken;
      if (!exploration::in_map(c, sc.map_size)) broken = "is outside the map";
      else if (grid.get(c).obstacle) broken = "stands on an obstacle";
      else if (grid.get(c).occupant != static_cast<int32_t>(k))
        broken = grid.get(c).occupant >= 0 ? fmt::format("shares its cell with robot {}", grid.get(c).occupant)
                                           : "is not its cell's occupant in the grid";
      if (broken.empty()) continue;
      detail = fmt::format("{} robot(s) on a {} x {} map: after the step robot {} at ({}, {}) {} (seed {}; confirmed "
                           "by running IndexOrder::plan)",
                           n, sc.map_size, sc.map_size, k, c[0], c[1], broken, seed);
      return true;
    }
  }
  return false;
}

// One planning step's query: from a valid state, the step leaves one. `one_mover`: only robot
// 0's pass of the robots' loop (the induction step), else IndexOrder::plan. The robots choose by
// `choice` (any_free: any choice the choice lemma allows).
Check check_step(Session& session, exploration::RuleSet set, int s_range, int robots, bool one_mover,
                 world::ChoiceMode choice) {
  StepWorld before(set, s_range, robots, choice);
  StepWorld after = before;
  plan(after, one_mover);
  sym::Bool pre = before.cfg.scenario.map_size >= 1 && before.cfg.scenario.map_size <= exploration::kMapSizeMax;
  sym::Bool post(true);
  for (int k = 0; k < robots; ++k) {
    pre = pre && robot_ok(before.cfg, before.env, before.grid, k);
    post = post && robot_ok(after.cfg, after.env, after.grid, k);
  }
  // Cells, offsets and indices as mathematical integers (linear arithmetic and congruence: a
  // window's cells are distinct at once, where bit-vectors would be blasted).
  Translator t(session, RealTheory::real, false, 0);
  z3::solver s = session.make_preprocessed_solver();
  s.add(t(pre));
  s.add(!t(post));
  s.add(t.side_conditions());
  const std::string label = fmt::format("{}-{}-{}-s{}-n{}", one_mover ? "robot" : "step",
                                        exploration::rules_of(set).name,
                                        choice == world::ChoiceMode::exact ? "exact" : "lemma", s_range, robots);
  const z3::check_result r = session.check_preprocessed(s, label);
  if (r != z3::sat) return {r, ""};
  std::string detail;
  if (replay_step(s.get_model(), t, before, set, s_range, detail)) return {z3::sat, label + ": " + detail};
  return {z3::unknown, label + ": NOT reproduced by the executed IndexOrder::plan"};
}

// A step with the choice lemma in place of the choice; a counterexample the executed step does
// not reproduce is asked again with the spec's choose_rule itself (the abstraction may allow a
// choice choose_rule never makes): its answer stands.
Check check_step_by_lemma(Session& session, exploration::RuleSet set, int s_range, int robots, bool one_mover) {
  const Check abstract = check_step(session, set, s_range, robots, one_mover, world::ChoiceMode::any_free);
  if (abstract.result != z3::unknown || abstract.detail.empty()) return abstract;
  const Check exact = check_step(session, set, s_range, robots, one_mover, world::ChoiceMode::exact);
  if (exact.result == z3::unknown && !exact.detail.empty())
    return {z3::unknown, exact.detail + (one_mover ? " (a state every robot's invariant holds in, but the step from it "
                                                     "is not reproduced: NOT a counterexample)"
                                                   : ": a spurious counterexample")};
  return exact;
}

Outcome run_occupancy(Session& session) {
  auto settle = [&](const Check& c) -> std::optional<Outcome> {
    if (c.result == z3::sat) return Outcome{Verdict::refuted, "sat: " + c.detail, {}};
    if (c.result != z3::unsat)
      return Outcome{Verdict::unknown, c.detail.empty() ? "unknown on query " + session.queries().back().label : c.detail, {}};
    return std::nullopt;
  };
  for (int s_range = 1; s_range <= kMaxRange; ++s_range)
    for (exploration::RuleSet set : kRuleSets)
      if (auto o = occupancy::choice_lemma(session, set, s_range, true)) return *o;
  // A whole step from the entry point with the spec's own choice (every function the step runs,
  // the pheromone the choice reads included), then the lemma in its place.
  for (exploration::RuleSet set : kRuleSets)
    if (auto o = settle(check_step(session, set, 1, 1, false, world::ChoiceMode::exact))) return *o;
  for (int s_range = 1; s_range <= kMaxRange; ++s_range)
    for (exploration::RuleSet set : kRuleSets) {
      if (auto o = settle(check_step_by_lemma(session, set, s_range, 1, false))) return *o;
      if (auto o = settle(check_step_by_lemma(session, set, s_range, 2, true))) return *o;
    }
  return {Verdict::proved,
          fmt::format("unsat: the choice lemma (deterministic and stochastic, s_range 1..{}); a whole step of one robot "
                      "with the spec's choice (s_range 1); the planning stage with any choice the lemma allows: whole "
                      "steps of one robot from IndexOrder::plan, and one robot's plan_robot against any other, so every "
                      "number of robots; {} queries",
                      kMaxRange, session.queries().size()),
          {}};
}

}  // namespace

namespace occupancy {

std::vector<sym::NodePtr> planning_step_quantities(exploration::RuleSet rule, int s_range, int robots) {
  StepWorld w(rule, s_range, robots);
  exploration::IndexOrder{}.plan(w.cfg, w.env, w.grid);
  std::vector<sym::NodePtr> out;
  for (const world::Robot& r : w.env.robots) {
    out.push_back(r.cell[0].node());
    out.push_back(r.cell[1].node());
    out.push_back(w.grid.occupant(r.cell).node());
    out.push_back(w.grid.obstacle(r.cell).node());
  }
  return out;
}

}  // namespace occupancy

std::vector<Obligation> occupancy_obligations() {
  return {Obligation{
      "occupancy",
      "One planning step of the deterministic or stochastic rule set, from a state in which every robot is in the map, "
      "off obstacles and named by the grid as its cell's occupant, keeps all three (so no two robots share a cell), for "
      "every number of robots and every map.",
      Verdict::proved,
      {"the step is the spec's IndexOrder::plan with everything under it (plan_robot, decide_on_grid, gather_candidates, "
       "window_around, choose, decide, apply_decision_to_grid, apply_decision_to_robot), interpreted on a symbolic map: its "
       "size free up to kMapSizeMax, each cell's obstacle flag, occupant, visit and pheromone uninterpreted functions of the "
       "cell (any contents), the grid a store of those plus the step's writes (the model's DenseGrid; conformance holds the "
       "library's LazyGrid to it)",
       "the choice lemma: choose_rule over a window of any contents (each cell present or not, blocked or not, any "
       "pheromone; phi = 1 so a key is the pheromone); the stochastic rules' draws are free choices in their ranges",
       "the step's queries put the lemma in place of the choice (any target the lemma allows: sound, every choice "
       "choose_rule makes is one of these); a counterexample the executed step does not reproduce is asked again with "
       "choose_rule itself",
       "whole steps of one robot from IndexOrder::plan (with the spec's own choice at s_range 1); for every number of "
       "robots, induction over the robots' loop: one robot's plan_robot keeps its own invariant and any other robot's "
       "(the invariant is per robot, and robots plan one after another in index order)",
       "s_range 1..3; cells and indices as mathematical integers (maps of any size up to kMapSizeMax), window indices "
       "8-bit in the choice lemma",
       "a counterexample counts only when the executed code reproduces it: choose() for the lemma, IndexOrder::plan on a "
       "concrete grid holding the model's map for a step (stochastic rules: with one of the seeds 0..999)"},
      run_occupancy,
      [] { return occupancy::planning_step_quantities(exploration::RuleSet::stochastic, 1, 2); }}};
}

}  // namespace swarmcheck::proofs
