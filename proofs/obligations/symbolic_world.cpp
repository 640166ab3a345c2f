#include "proofs/obligations/symbolic_world.hpp"

#include "proofs/obligations/replay_grid.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace swarmcheck::proofs::world {

sym::Bool same_cell(const Cell& a, const Cell& b) { return a[0] == b[0] && a[1] == b[1]; }

exploration::ChoiceT<S> choose(const exploration::RuleDescriptor& rules, const Terms& terms,
                               std::span<const exploration::SymbolicCandidate> c,
                               const exploration::SymbolicDrawSite& site) {
  if (terms.mode == ChoiceMode::exact) return exploration::choose(rules, terms.exact, c, site);
  const sym::Int best = sym::Int::var(site.name + ".best"), target = sym::Int::var(site.name + ".target");
  sym::Bool best_ok(false), target_ok(false);
  for (std::size_t k = 0; k < c.size(); ++k) {
    const sym::Bool here = c[k].present;
    best_ok = best_ok || (best == static_cast<int32_t>(k) && here);
    target_ok = target_ok || (target == static_cast<int32_t>(k) && here &&
                              (terms.mode == ChoiceMode::any_free ? !c[k].blocked : sym::Bool(true)));
  }
  return {sym::select(best_ok, best, sym::Int(-1)), sym::select(target_ok, target, sym::Int(-1)),
          sym::Bool::var(site.name + ".fallback")};
}

Config symbolic_config(exploration::RuleSet rule, int32_t s_range, ChoiceMode choice) {
  Config c;
  c.scenario.map_size = sym::Int::var("map_size");
  c.scenario.cell_size = sym::Real::var("cell_size");
  c.scenario.params.s_range = s_range;
  c.scenario.params.step_size = sym::Real::var("step_size");
  c.rules = &exploration::rules_of(rule);
  c.terms = {{sym::Real(1.0), sym::Real::var("eta_term"), sym::Real::var("thesis_best_start")}, choice};
  c.deposit.params = {sym::Real::var("max_ph"), sym::Real::var("a1"), sym::Real::var("epsilon"), sym::Real::var("a2")};
  const sym::Real ertu = sym::Real::var("ertu");
  c.decay = exploration::make_decay_table_rule<S>(exploration::evaporation_factor_rule<S>(ertu, c.scenario.params.step_size));
  c.ertu_dt = ertu * c.scenario.params.step_size;
  return c;
}

Robot merge(const sym::Bool& c, const Robot& a, const Robot& b) {
  return {{sym::select(c, a.cell[0], b.cell[0]), sym::select(c, a.cell[1], b.cell[1])},
          {sym::select(c, a.waypoint[0], b.waypoint[0]), sym::select(c, a.waypoint[1], b.waypoint[1])}};
}

Environment symbolic_environment(const Config& cfg, int robots, const std::string& name, int64_t tick) {
  Environment e;
  e.handshake = {sym::Bool::var(name + "_flag"), sym::Bool::var(name + "_env_out")};
  e.tick = tick;
  e.progress.visited = sym::Int(0);
  for (int k = 0; k < robots; ++k) {
    const Cell c{sym::Int::var(fmt::format("{}_i_{}", name, k)), sym::Int::var(fmt::format("{}_j_{}", name, k))};
    e.robots.push_back({c, exploration::centre_of_rule<S>(c, cfg.scenario.cell_size)});
    e.deposit_centre.push_back(c);
  }
  return e;
}

Grid::Grid(const Config& cfg, std::string name, int64_t tick, int64_t written)
    : cfg_(&cfg), name_(std::move(name)), tick_(tick), written_(written) {
  if (written > tick) throw std::invalid_argument("a cell cannot be written after the grid's tick");
}

std::vector<sym::Int> Grid::args(const Cell& c) const { return {c[0], c[1]}; }

// A value written `age` ticks ago, as the grids read it now (the spec's cell rules).
sym::Real Grid::aged(const sym::Real& value, int64_t age) const {
  if (cfg_->rules->evaporation == exploration::Evaporation::decay_function) {
    auto it = factor_->find(age);
    if (it == factor_->end()) it = factor_->emplace(age, exploration::decay_factor_rule<S>(cfg_->decay, age)).first;
    return exploration::decayed_pheromone_rule<S>(value, it->second);
  }
  sym::Real v = value;
  for (int64_t k = 0; k < age; ++k) v = exploration::thesis_evaporate_rule<S>(v, cfg_->ertu_dt);
  return v;
}

sym::Bool Grid::obstacle(const Cell& c) const {
  sym::Bool v = sym::bool_function(name_ + ".obstacle", args(c));
  for (const Write& w : writes_)
    if (w.field == Field::obstacle) v = sym::select(w.guard && same_cell(c, w.cell), w.flag, v);
  return v;
}

sym::Int Grid::occupant(const Cell& c) const {
  sym::Int v = sym::int_function(name_ + ".occupant", args(c));
  for (const Write& w : writes_)
    if (w.field == Field::occupant) v = sym::select(w.guard && same_cell(c, w.cell), w.integer, v);
  return v;
}

sym::Bool Grid::visited(const Cell& c) const {
  sym::Bool v = sym::bool_function(name_ + ".visited", args(c));
  for (const Write& w : writes_)
    if (w.field == Field::visited) v = sym::select(w.guard && same_cell(c, w.cell), w.flag, v);
  return v;
}

sym::Real Grid::stored(const Cell& c) const { return sym::real_function(name_ + ".pheromone", args(c)); }

sym::Real Grid::pheromone(const Cell& c, int64_t tick) const {
  if (tick != tick_) throw std::logic_error("the symbolic grid is read at its own tick only (as DenseGrid)");
  sym::Real v = aged(stored(c), tick_ - written_);
  for (const Write& w : writes_)
    if (w.field == Field::pheromone) v = sym::select(w.guard && same_cell(c, w.cell), aged(w.value, tick_ - w.tick), v);
  return v;
}

exploration::SymbolicCandidate Grid::candidate(const Cell& c, int64_t tick) const {
  return {c, pheromone(c, tick), obstacle(c) || occupant(c) >= 0, sym::Bool(true)};
}

void Grid::release(const Cell& c) { writes_.push_back({true, c, Field::occupant, false, sym::Int(-1), 0.0, 0}); }
void Grid::occupy(const Cell& c, int32_t r) { writes_.push_back({true, c, Field::occupant, false, sym::Int(r), 0.0, 0}); }
sym::Bool Grid::mark_visited(const Cell& c) {
  const sym::Bool newly = !visited(c);
  writes_.push_back({true, c, Field::visited, true, sym::Int(0), 0.0, 0});
  return newly;
}
void Grid::set_obstacle(const Cell& c) { writes_.push_back({true, c, Field::obstacle, true, sym::Int(0), 0.0, 0}); }
void Grid::evaporate(int64_t tick) {
  if (tick != tick_ + 1) throw std::logic_error("the grid evaporates one tick at a time");
  tick_ = tick;
}
void Grid::deposit(const Cell& c, int64_t tick, const sym::Real& amount) {
  if (tick != tick_) throw std::logic_error("a deposit is made at the grid's tick");
  writes_.push_back(
      {true, c, Field::pheromone, false, sym::Int(0), exploration::deposited_pheromone_rule<S>(pheromone(c, tick), amount), tick});
}

Grid merge(const sym::Bool& c, const Grid& a, const Grid& b) {
  if (a.cfg_ != b.cfg_ || a.name_ != b.name_ || a.tick_ != b.tick_ || a.writes_.size() < b.writes_.size())
    throw std::logic_error("merge: not the same grid");
  Grid out = b;
  for (std::size_t k = b.writes_.size(); k < a.writes_.size(); ++k) {
    Grid::Write w = a.writes_[k];
    w.guard = c && w.guard;
    out.writes_.push_back(std::move(w));
  }
  return out;
}

}  // namespace swarmcheck::proofs::world

namespace swarmcheck::proofs {

double ReplayGrid::pheromone(exploration::CellIndex c, int64_t tick) const {
  const Content& x = get(c);
  const int64_t age = tick - x.written;
  if (cfg_->rules->evaporation == exploration::Evaporation::decay_function)
    return exploration::decayed_pheromone(x.value, exploration::decay_factor_rule<num::Concrete>(cfg_->decay, age));
  double v = x.value;
  for (int64_t k = 0; k < age; ++k) v = exploration::thesis_evaporate(v, cfg_->ertu_dt);
  return v;
}

}  // namespace swarmcheck::proofs
