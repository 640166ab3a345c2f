#pragma once
// The optimised Environment: the spec's Environment step (spec/exploration/environment_step.hpp)
// on a lazy grid, with stages that give the spec's index-order result faster: windows prefetched
// a few robots ahead, and for many robots, decisions in parallel by independent groups.
#include <cstdint>
#include <optional>
#include <vector>

#include "impl/exploration/lazy_grid.hpp"
#include "spec/exploration/environment_step.hpp"
#include "swarmcheck/exploration.hpp"

namespace swarmcheck::impl::exploration {

class Environment {
 public:
  Environment(const swarmcheck::exploration::Scenario& s, const ExplorationOptions& options);
  Environment(const Environment&) = delete;   // the grid points into cfg_
  Environment& operator=(const Environment&) = delete;

  void step(bool all_arrived);

  const swarmcheck::exploration::EnvironmentConfig& config() const { return cfg_; }
  const swarmcheck::exploration::Scenario& scenario() const { return cfg_.scenario; }
  const swarmcheck::exploration::EnvironmentState& state() const { return env_; }
  swarmcheck::exploration::Cell cell(CellIndex c) const;
  uint64_t digest() const { return swarmcheck::exploration::pheromone_digest(cfg_, grid_, env_.tick); }

  // The stages of a step (spec IndexOrder's results, computed faster).
  int64_t plan(swarmcheck::exploration::EnvironmentState& env, LazyGrid& grid) const;
  void deposit(const swarmcheck::exploration::EnvironmentState& env, LazyGrid& grid) const;

 private:
  int64_t plan_sequential(swarmcheck::exploration::EnvironmentState& env, LazyGrid& grid) const;
  int64_t plan_grouped(swarmcheck::exploration::EnvironmentState& env, LazyGrid& grid) const;
  void prefetch(CellIndex c) const;

  swarmcheck::exploration::EnvironmentConfig cfg_;
  ExplorationOptions options_;
  LazyGrid grid_;
  swarmcheck::exploration::EnvironmentState env_;
  mutable std::vector<Candidate> scratch_;   // the sequential stage's candidates, reused
};

}  // namespace swarmcheck::impl::exploration
