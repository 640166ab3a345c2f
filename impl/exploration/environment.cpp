#include "impl/exploration/environment.hpp"

#include <algorithm>

namespace swarmcheck::impl::exploration {

namespace spec = swarmcheck::exploration;

namespace {
constexpr std::size_t kPrefetchAhead = 4;   // robots
constexpr int32_t kPrefetchRangeMax = 2;    // s_range up to which windows are prefetched

// The stages the spec's environment_step calls, bound to this Environment.
struct Stages {
  const Environment* env;
  int64_t plan(const spec::EnvironmentConfig&, spec::EnvironmentState& s, LazyGrid& g) const {
    return env->plan(s, g);
  }
  void deposit(const spec::EnvironmentConfig&, const spec::EnvironmentState& s, LazyGrid& g) const {
    env->deposit(s, g);
  }
};
}  // namespace

Environment::Environment(const spec::Scenario& s, const ExplorationOptions& options)
    : cfg_(spec::make_environment_config(s)),
      options_(options),
      grid_(cfg_),
      env_(spec::initial_environment(cfg_, grid_)) {}

spec::Cell Environment::cell(CellIndex c) const {
  SWARM_DEMAND(spec::in_map(c, cfg_.scenario.map_size));
  return grid_.cell(c, env_.tick);
}

void Environment::step(bool all_arrived) { spec::environment_step(cfg_, env_, grid_, all_arrived, Stages{this}); }

int64_t Environment::plan(spec::EnvironmentState& env, LazyGrid& grid) const {
  if (static_cast<int64_t>(env.robots.size()) >= options_.parallel_min_robots) return plan_grouped(env, grid);
  return plan_sequential(env, grid);
}

void Environment::prefetch(CellIndex c) const {
  if (cfg_.scenario.params.s_range <= kPrefetchRangeMax) grid_.prefetch_window(c, cfg_.scenario.params.s_range);
}

// Robots are handled in index order, so the windows of the next few are known before they are
// needed: asking for them early hides the memory latency of big maps.
int64_t Environment::plan_sequential(spec::EnvironmentState& env, LazyGrid& grid) const {
  const std::size_t n = env.robots.size();
  for (std::size_t r = 0; r < std::min(n, kPrefetchAhead); ++r) prefetch(env.robots[r].cell);
  int64_t newly = 0;
  for (std::size_t r = 0; r < n; ++r) {
    if (r + kPrefetchAhead < n) prefetch(env.robots[r + kPrefetchAhead].cell);
    newly += spec::plan_robot(cfg_, env, grid, static_cast<int32_t>(r), scratch_);
  }
  return newly;
}

void Environment::deposit(const spec::EnvironmentState& env, LazyGrid& grid) const {
  const std::size_t n = env.deposit_centre.size();
  for (std::size_t r = 0; r < n; ++r) {
    if (r + kPrefetchAhead < n) prefetch(env.deposit_centre[r + kPrefetchAhead]);
    spec::deposit_around(cfg_, grid, env.deposit_centre[r], env.tick);
  }
}

}  // namespace swarmcheck::impl::exploration
