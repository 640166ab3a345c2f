#include "conformance/exploration/lockstep.hpp"

#include "conformance/exploration/transition.hpp"
#include "model/exploration/exploration_model.hpp"
#include "spec/util/hana_diff.hpp"

namespace swarmcheck::conformance {

using namespace exploration;

std::string Divergence::describe() const {
  if (spec_violation) return "step " + std::to_string(step) + ": the model broke the spec: " + impl;
  return "step " + std::to_string(step) + ": " + path + " model=" + model + " impl=" + impl;
}

namespace {

std::optional<Divergence> compare_cells(const model::ExplorationModel& m, const Exploration& x, int64_t step) {
  const int32_t n = m.scenario().map_size;
  for (int32_t i = 0; i < n; ++i)
    for (int32_t j = 0; j < n; ++j) {
      const std::string path = "cells[" + std::to_string(i) + "][" + std::to_string(j) + "]";
      // pheromone_tick is bookkeeping (dense vs lazy), not observable: compare the rest.
      Cell a = m.environment().cell({i, j}), b = x.cell({i, j});
      a.pheromone_tick = b.pheromone_tick = 0;
      if (auto d = json_io::first_difference(a, b, path)) return Divergence{step, d->path, d->a, d->b, false};
    }
  return std::nullopt;
}

}  // namespace

std::optional<Divergence> run_lockstep(const Scenario& s, const ExplorationOptions& options) {
  model::ExplorationModel m(s);
  Exploration x(s, options);
  StepRecord before = m.record();
  if (auto d = json_io::first_difference(before, x.record()))
    return Divergence{0, d->path, d->a, d->b, false};
  if (auto d = compare_cells(m, x, 0)) return d;
  while (!m.done() || !x.done()) {
    m.step();
    x.step();
    const StepRecord after = m.record();
    if (std::string e = check_transition(s, before, after); !e.empty())
      return Divergence{after.step, "", "", e, true};
    if (auto d = json_io::first_difference(after, x.record()))
      return Divergence{after.step, d->path, d->a, d->b, false};
    const bool planned = after.planning_steps != before.planning_steps;
    if (planned || m.done() || after.step % 16 == 0)
      if (auto d = compare_cells(m, x, after.step)) return d;
    before = after;
  }
  return std::nullopt;
}

}  // namespace swarmcheck::conformance
