#pragma once
// A concrete grid for replaying a counterexample through the executed code: the grid operations
// of spec/exploration/environment_step.hpp with the model's DenseGrid semantics (a cell's
// pheromone is its written value aged by the spec's cell rules), over a sparse map so that a
// counterexample's cells may lie anywhere, even outside the map (a broken window reads them:
// such a cell is free and holds no pheromone, and the replay then shows the robot leaving).
#include <cstdint>
#include <map>

#include "spec/exploration/environment_step.hpp"

namespace swarmcheck::proofs {

class ReplayGrid {
 public:
  struct Content {
    double value = 0;       // pheromone as written at `written`
    int64_t written = 0;
    bool visited = false;
    bool obstacle = false;
    int32_t occupant = -1;
  };

  ReplayGrid(const exploration::EnvironmentConfig& cfg, int64_t tick) : cfg_(&cfg), tick_(tick) {}

  exploration::Candidate candidate(exploration::CellIndex c, int64_t tick) const {
    const Content& x = get(c);
    return {c, pheromone(c, tick), x.obstacle || x.occupant >= 0};
  }
  double pheromone(exploration::CellIndex c, int64_t tick) const;
  void release(exploration::CellIndex c) { at(c).occupant = -1; }
  void occupy(exploration::CellIndex c, int32_t r) { at(c).occupant = r; }
  bool mark_visited(exploration::CellIndex c) {
    const bool newly = !get(c).visited;
    at(c).visited = true;
    return newly;
  }
  void set_obstacle(exploration::CellIndex c) { at(c).obstacle = true; }
  void evaporate(int64_t tick) { tick_ = tick; }
  void deposit(exploration::CellIndex c, int64_t tick, double amount) {
    Content& x = at(c);
    x.value = exploration::deposited_pheromone(pheromone(c, tick), amount);
    x.written = tick;
  }

  Content& at(exploration::CellIndex c) { return cells_[c]; }
  const Content& get(exploration::CellIndex c) const {
    const auto it = cells_.find(c);
    return it == cells_.end() ? empty_ : it->second;
  }
  int64_t tick() const { return tick_; }

 private:
  const exploration::EnvironmentConfig* cfg_;
  int64_t tick_;
  std::map<exploration::CellIndex, Content> cells_;
  Content empty_{};
};

static_assert(exploration::EnvironmentGrid<ReplayGrid>);

}  // namespace swarmcheck::proofs
