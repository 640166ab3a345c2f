#include "spec/exploration/environment_step.hpp"

#include "spec/util/demand.hpp"

namespace swarmcheck::exploration {

EnvironmentConfig make_environment_config(const Scenario& s) {
  return EnvironmentConfig{s,
                           &rules_of(s.rule),
                           choice_terms(s.params),
                           DepositKernel(s.params, s.map_size),
                           make_decay_table(evaporation_factor(s.params)),
                           s.params.ertu * s.params.step_size};
}

void update_progress(Progress& p, int64_t tick, double step_size_s) {
  SWARM_DEMAND(p.free_cells > 0);
  if (p.completion_step) return;   // eP and sTime are frozen once exploration is complete
  p.eP = exploration_percent(p.visited, p.free_cells);
  p.sTime = static_cast<double>(tick) * step_size_s;
  if (p.eP >= 100.0) p.completion_step = tick;
}

}  // namespace swarmcheck::exploration
