#pragma once
// The world the Environment's stages run in for a proof: a symbolic configuration, state and
// grid, on which proofs/ interprets spec/'s own templates (environment_step.hpp: gather, choose,
// decide, the grid effects, the deposit stage, IndexOrder, environment_stages) exactly as model/
// and impl/ run them on theirs. Nothing here decides anything: the grid is a store.
//
// The grid is the abstraction of the model's DenseGrid (a map from cells to contents; the
// conformance harness holds impl's LazyGrid to it): each content of a cell is an uninterpreted
// function of the cell (the map before the step: any obstacles, occupants, visits, pheromone),
// followed by the step's writes, each under the condition it was made in (a write inside a
// num::when on a symbolic condition). Pheromone is read as the grids read it, through the spec's
// cell rules: the value written at tick w, k = t - w ticks later, is
//   decay function:   decayed_pheromone_rule(value, decay_factor_rule(table, k))
//   literal update:   thesis_evaporate_rule applied k times
// and a deposit writes deposited_pheromone_rule(current, amount) at the current tick.
#include <array>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "spec/exploration/choice.hpp"
#include "spec/exploration/decay.hpp"
#include "spec/exploration/deposit.hpp"
#include "spec/exploration/handshake.hpp"
#include "spec/exploration/neighbourhood.hpp"
#include "spec/exploration/rule_set.hpp"

namespace swarmcheck::proofs::world {

using S = num::Symbolic;
using Cell = exploration::CellOf<S>;

struct Scenario {
  sym::Int map_size;
  sym::Real cell_size;
  struct Params {
    int32_t s_range = 1;
    sym::Real step_size;
  } params;
  uint64_t seed = 0;
  exploration::Mode mode = exploration::Mode::cosim;
};

// How the world's robots choose. exact: the spec's choose_rule. The others replace it by what a
// lemma about choose_rule proves of it, for any window (occupancy.cpp proves both):
//   any_present   the best and the target are each a present candidate or -1
//   any_free      besides, the target is a free one
// so that a step's query need not unroll the choice (sound: every choice choose_rule makes is one
// of these; a counterexample of the abstraction is asked again exactly).
enum class ChoiceMode { exact, any_present, any_free };

struct Terms {
  exploration::ChoiceTermsT<S> exact;
  ChoiceMode mode = ChoiceMode::exact;
};

// decide_on_grid's choose() for the world's Terms (found by argument-dependent lookup).
exploration::ChoiceT<S> choose(const exploration::RuleDescriptor& rules, const Terms& terms,
                               std::span<const exploration::SymbolicCandidate> candidates,
                               const exploration::SymbolicDrawSite& site);

struct Config {
  using Domain = S;
  Scenario scenario;
  const exploration::RuleDescriptor* rules = nullptr;
  Terms terms;
  exploration::SymbolicDepositKernel deposit;
  exploration::DecayTableT<S> decay;
  sym::Real ertu_dt;
};

// The configuration with every parameter a named variable ("map_size", "ertu", ...): the map of
// any size, the algorithm's parameters any values (their domains are the obligation's to state).
// The decay table is make_decay_table_rule of evaporation_factor_rule, as make_environment_config
// builds it; the choice terms are phi = 1 (a key is the pheromone) and free eta and start terms.
Config symbolic_config(exploration::RuleSet rule, int32_t s_range, ChoiceMode choice = ChoiceMode::exact);

struct Robot {
  Cell cell;
  std::array<sym::Real, 2> waypoint;
};
Robot merge(const sym::Bool& c, const Robot& a, const Robot& b);

// Progress (eP, sTime) is not a property of any obligation: only the visited count is kept.
struct Progress {
  sym::Int visited;
};
inline void update_progress(Progress&, int64_t /*tick*/, const sym::Real& /*step_size*/) {}

struct Environment {
  exploration::HandshakeStateT<S> handshake;
  int64_t tick = 0;
  int64_t planning_steps = 0;
  std::vector<Robot> robots;
  std::vector<Cell> deposit_centre;
  Progress progress;
};

// n robots at cells "<name>_i_k", "<name>_j_k" (free), waypoints their centres, deposit centres
// their cells, at tick `tick`.
Environment symbolic_environment(const Config& cfg, int robots, const std::string& name, int64_t tick);

class Grid {
 public:
  // The map before the step, its contents the functions "<name>.obstacle" etc. of the cell; the
  // grid is at `tick`, every cell's pheromone written at tick `written` (<= tick).
  Grid(const Config& cfg, std::string name, int64_t tick, int64_t written);

  // The grid operations of environment_step.hpp.
  exploration::SymbolicCandidate candidate(const Cell& c, int64_t tick) const;
  sym::Real pheromone(const Cell& c, int64_t tick) const;
  void release(const Cell& c);
  void occupy(const Cell& c, int32_t r);
  sym::Bool mark_visited(const Cell& c);
  void set_obstacle(const Cell& c);
  void evaporate(int64_t tick);
  void deposit(const Cell& c, int64_t tick, const sym::Real& amount);

  sym::Bool obstacle(const Cell& c) const;
  sym::Int occupant(const Cell& c) const;   // a robot's index, or -1
  sym::Bool visited(const Cell& c) const;
  // The pheromone as written before the step (the base map's value at its write tick).
  sym::Real stored(const Cell& c) const;
  // A value written `age` ticks ago, as the grid reads it now (the spec's cell rules).
  sym::Real aged(const sym::Real& value, int64_t age) const;
  int64_t written() const { return written_; }
  int64_t tick() const { return tick_; }

  // a and b are the same grid, a with the writes of an effect taken under c.
  friend Grid merge(const sym::Bool& c, const Grid& a, const Grid& b);

 private:
  enum class Field { obstacle, occupant, visited, pheromone };
  struct Write {
    sym::Bool guard;
    Cell cell;
    Field field;
    sym::Bool flag;
    sym::Int integer;
    sym::Real value;   // pheromone: the value written
    int64_t tick = 0;  // pheromone: the tick it was written at
  };
  std::vector<sym::Int> args(const Cell& c) const;

  const Config* cfg_;
  // decay_factor_rule by age: one expression per age, shared by the copies num::when makes.
  std::shared_ptr<std::map<int64_t, sym::Real>> factor_ = std::make_shared<std::map<int64_t, sym::Real>>();
  std::string name_;
  int64_t tick_;
  int64_t written_;
  std::vector<Write> writes_;
};

sym::Bool same_cell(const Cell& a, const Cell& b);

}  // namespace swarmcheck::proofs::world
