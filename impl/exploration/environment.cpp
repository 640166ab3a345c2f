#include "impl/exploration/environment.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>
#include <thread>

#include <tbb/info.h>

namespace swarmcheck::impl::exploration {

namespace spec = swarmcheck::exploration;

namespace {
constexpr std::size_t kPrefetchAhead = 4;   // robots
constexpr int32_t kPrefetchRangeMax = 2;    // s_range up to which windows are prefetched
// Below this many window cells in a stage (robots x (2 s + 1)^2), cutting strips and handing them
// to threads costs more than it saves (bench_exploration, threads 1 against all).
constexpr int64_t kParallelMinWindowCells = int64_t{1} << 15;

// Whether robots are dense enough for the walled-in test to pay: it costs a robot that is not
// walled in a cell read or two (3-4 % of a step at 10^4 robots on 256^2 or 1024^2), and saves a
// walled-in robot its gathering and choice (10^6 robots on 1024^2, two in three walled in: 1.45x
// a step). With the blocked cells (robots and obstacles) spread at random, a share of about
// density^(window cells - 1) of the robots is walled in: worth it from one robot in eight.
bool dense(const spec::Scenario& s) {
  const double cells = static_cast<double>(s.map_size) * static_cast<double>(s.map_size);
  const double density = static_cast<double>(s.robots.size() + s.obstacles.size()) / cells;
  const double side = 2.0 * s.params.s_range + 1.0;
  return std::pow(std::min(density, 1.0), side * side - 1.0) >= 1.0 / 8.0;
}

int64_t nanoseconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - t0).count();
}

int32_t threads_of(const swarmcheck::exploration::ExplorationOptions& o) {
  if (o.threads > 0) return o.threads;
  return static_cast<int32_t>(std::max(1u, std::thread::hardware_concurrency()));
}

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
      walled_in_stays_(spec::walled_in_decision(*cfg_.rules, CellIndex{0, 0}).has_value() &&
                       (options.walled_in_always || dense(cfg_.scenario))),
      threads_(threads_of(options)),
      // More threads than cores would only be refused by TBB (with a warning): the strips still
      // follow threads_, the arena the machine.
      arena_(std::min(threads_, tbb::info::default_concurrency())),
      env_(spec::initial_environment(cfg_, grid_, Stages{this})) {}

spec::Cell Environment::cell(CellIndex c) const {
  SWARM_DEMAND(spec::in_map(c, cfg_.scenario.map_size));
  return grid_.cell(c, env_.tick);
}

void Environment::step(bool all_arrived) { spec::environment_step(cfg_, env_, grid_, all_arrived, Stages{this}); }
void Environment::step_planned(bool planning) { spec::environment_stages(cfg_, env_, grid_, planning, Stages{this}); }

int32_t Environment::strips_for(std::size_t robots) const {
  if (threads_ <= 1 || robots < 2) return 1;
  const int64_t n = static_cast<int64_t>(robots);
  if (options_.parallel_min_robots > 0) {
    if (n < options_.parallel_min_robots) return 1;
  } else {
    const int64_t side = 2 * int64_t{cfg_.scenario.params.s_range} + 1;
    if (n * side * side < kParallelMinWindowCells) return 1;
  }
  // One strip per thread, each held by its thread for the whole stage: a strip more would be one
  // a thread takes over from its neighbour, holding it while the neighbour's own task spins.
  return threads_;
}

// A robot's decision touches only its window (s_range rows either side of its row), and its
// deposit only the window around its deposit centre: robots whose rows (centres' rows) are more
// than 2 s_range apart never touch the same cell. (One schedule for both stages, with reach
// 4 s_range around the rows robots start on, measured no faster: twice the edge robots.)
int64_t Environment::plan(spec::EnvironmentState& env, LazyGrid& grid) const {
  const int32_t strips = strips_for(env.robots.size());
  if (strips <= 1) return plan_sequential(env, grid);
  if (!tuned()) {
    if (const auto newly = plan_parallel(env, grid, strips)) return *newly;
    return plan_sequential(env, grid);
  }
  // The tuner times a planning step's two stages together, in one mode: the decisions' band
  // schedule serves the deposits too, so neither stage's cost alone tells which mode is faster.
  const auto t0 = std::chrono::steady_clock::now();
  std::optional<int64_t> newly;
  if (step_tuner_.next_parallel()) newly = plan_parallel(env, grid, strips);
  const bool parallel = newly.has_value();
  if (!parallel) newly = plan_sequential(env, grid);
  tuned_step_ = TunedStep{parallel, env.tick + 1, nanoseconds_since(t0)};
  return *newly;
}

std::optional<int64_t> Environment::plan_parallel(spec::EnvironmentState& env, LazyGrid& grid, int32_t strips) const {
  const int32_t reach = 2 * cfg_.scenario.params.s_range;
  // Each robot's record is written as it decides: no robot's decision reads another's record,
  // only its own cell (before it moves) and the grid. (Kept in per-strip buffers and written
  // after the stage, 36 bytes a robot streamed out and read back on the calling thread, the
  // records cost 10^6 robots ~8 ms a step more; measured side by side, strips forced: 0.98-1.09x
  // -> 1.17-1.26x one thread, and no loss at 10^4 or 10^5 robots.)
  const auto decide = [&](int32_t r, StripPlanning& p) { return plan_robot(env, grid, r, p.candidates); };
  const auto ahead = [&](int32_t r) { prefetch(env.robots[static_cast<std::size_t>(r)].cell); };
  cells_.resize(env.robots.size());
  for (std::size_t r = 0; r < cells_.size(); ++r) cells_[r] = env.robots[r].cell;
  int64_t newly = 0;
  // Built with twice the reach, the band schedule serves this step's deposits too: a robot's
  // deposit centre is within s_range of the cell it decides from, so two deposit windows that
  // meet belong to robots whose cells are within 4 s_range.
  band_for_deposit_tick_.reset();
  if (band_.build(cells_, cfg_.scenario.map_size, 2 * reach, strips)) {
    newly = stage([&] { return band_.run(arena_, strip_planning_, decide, ahead); });
    band_for_deposit_tick_ = env.tick + 1;
  } else {
    if (strips_.build(cells_, cfg_.scenario.map_size, reach, strips) <= 1) return std::nullopt;
    newly = stage([&] { return strips_.run(arena_, strip_planning_, decide, ahead); });
  }
  return newly;
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
    newly += plan_robot(env, grid, static_cast<int32_t>(r), scratch_);
  }
  return newly;
}

// The initialisation's deposits (tick 0; a step's come after its tick is counted) stay on this
// thread: done once, they cost less than the strips' waiting on a machine whose other core is
// busy (10^6 robots on 1024^2: ~0.15 s alone, 0.3-0.6 s more on two threads of a loaded VM).
void Environment::deposit(const spec::EnvironmentState& env, LazyGrid& grid) const {
  const std::size_t n = env.deposit_centre.size();
  const int32_t strips = env.tick == 0 ? 1 : strips_for(n);
  if (strips <= 1) return deposit_sequential(env, grid);
  if (!tuned()) {
    if (!deposit_parallel(env, grid, strips)) deposit_sequential(env, grid);
    return;
  }
  // The mode of this step's decisions (a tuned step plans before it deposits, at the tick before).
  const std::optional<TunedStep> step = std::exchange(tuned_step_, std::nullopt);
  SWARM_DEMAND(step && step->deposit_tick == env.tick);
  const auto t0 = std::chrono::steady_clock::now();
  const bool parallel = step->parallel && deposit_parallel(env, grid, strips);
  if (!parallel) deposit_sequential(env, grid);
  step_tuner_.record(parallel, step->plan_ns + nanoseconds_since(t0));
}

bool Environment::deposit_parallel(const spec::EnvironmentState& env, LazyGrid& grid, int32_t strips) const {
  const int32_t reach = 2 * cfg_.scenario.params.s_range;
  const auto deposit = [&](int32_t r, char&) {
    grid.deposit_window(cfg_, env.deposit_centre[static_cast<std::size_t>(r)], env.tick);
    return int64_t{0};
  };
  const auto ahead = [&](int32_t r) { prefetch(env.deposit_centre[static_cast<std::size_t>(r)]); };
  const bool planned_on_band = band_for_deposit_tick_ == env.tick;
  band_for_deposit_tick_.reset();
  if (planned_on_band || band_.build(env.deposit_centre, cfg_.scenario.map_size, reach, strips)) {
    stage([&] { return band_.run(arena_, no_scratch_, deposit, ahead); });
    return true;
  }
  if (strips_.build(env.deposit_centre, cfg_.scenario.map_size, reach, strips) <= 1) return false;
  stage([&] { return strips_.run(arena_, no_scratch_, deposit, ahead); });
  return true;
}

void Environment::deposit_sequential(const spec::EnvironmentState& env, LazyGrid& grid) const {
  const std::size_t n = env.deposit_centre.size();
  for (std::size_t r = 0; r < std::min(n, kPrefetchAhead); ++r) prefetch(env.deposit_centre[r]);
  for (std::size_t r = 0; r < n; ++r) {
    if (r + kPrefetchAhead < n) prefetch(env.deposit_centre[r + kPrefetchAhead]);
    grid.deposit_window(cfg_, env.deposit_centre[r], env.tick);
  }
}

}  // namespace swarmcheck::impl::exploration
