#pragma once
// The optimised Environment: the spec's Environment step (spec/exploration/environment_step.hpp)
// on a lazy grid, with stages that give the spec's index-order result faster: windows prefetched
// a few robots ahead, and for enough work, decisions and deposits in parallel over strips of the
// map (band_schedule.hpp for sparse robots, strip_schedule.hpp otherwise) with exactly the
// index-order result, where timing shows it faster than one thread (stage_tuner.hpp).
#include <tbb/task_arena.h>

#include <cstdint>
#include <optional>
#include <vector>

#include "impl/exploration/band_schedule.hpp"
#include "impl/exploration/cache_line_allocator.hpp"
#include "impl/exploration/lazy_grid.hpp"
#include "impl/exploration/stage_tuner.hpp"
#include "impl/exploration/strip_schedule.hpp"
#include "impl/exploration/warm_workers.hpp"
#include "spec/exploration/environment_step.hpp"
#include "swarmcheck/exploration.hpp"

namespace swarmcheck::impl::exploration {

class Environment {
 public:
  Environment(const swarmcheck::exploration::Scenario& s, const ExplorationOptions& options);
  Environment(const Environment&) = delete;   // the grid points into cfg_
  Environment& operator=(const Environment&) = delete;

  void step(bool all_arrived);
  // A step whose planning another protocol decided (the handshake state is left as it is).
  void step_planned(bool planning);

  const swarmcheck::exploration::EnvironmentConfig& config() const { return cfg_; }
  const swarmcheck::exploration::Scenario& scenario() const { return cfg_.scenario; }
  const swarmcheck::exploration::EnvironmentState& state() const { return env_; }
  swarmcheck::exploration::Cell cell(CellIndex c) const;
  uint64_t digest() const { return swarmcheck::exploration::pheromone_digest(cfg_, grid_, env_.tick); }

  // The stages of a step (spec IndexOrder's results, computed faster).
  int64_t plan(swarmcheck::exploration::EnvironmentState& env, LazyGrid& grid) const;
  void deposit(const swarmcheck::exploration::EnvironmentState& env, LazyGrid& grid) const;

  // The threads this Environment (and the master's robots) may use, and where they run (its
  // workers, if kept warm after a stage, are called back first).
  int32_t threads() const { return threads_; }
  tbb::task_arena& arena() const {
    warm_.wake();
    return arena_;
  }

 private:
  int64_t plan_sequential(swarmcheck::exploration::EnvironmentState& env, LazyGrid& grid) const;
  // On the strips; nullopt (nothing done) when the robots give only one strip.
  std::optional<int64_t> plan_parallel(swarmcheck::exploration::EnvironmentState& env, LazyGrid& grid,
                                       int32_t strips) const;
  void deposit_sequential(const swarmcheck::exploration::EnvironmentState& env, LazyGrid& grid) const;
  bool deposit_parallel(const swarmcheck::exploration::EnvironmentState& env, LazyGrid& grid, int32_t strips) const;
  // Whether strips or one thread is chosen by timing both (StageTuner): unless the options fix
  // the threshold (parallel_min_robots > 0), which the tests use to force the strips.
  bool tuned() const { return options_.parallel_min_robots == 0; }
  // How many strips a stage over `robots` robots is worth cutting (1: do it on this thread).
  int32_t strips_for(std::size_t robots) const;
  void prefetch(CellIndex c) const;
  // Robot r's decision, on the grid and its record (spec::plan_robot's result); a walled-in robot
  // (no free cell in its window) skips its choice where the rule set allows
  // (spec::walled_in_decision): in a dense swarm most robots are walled in. Returns the cells newly
  // marked visited.
  template <class Candidates>
  int64_t plan_robot(swarmcheck::exploration::EnvironmentState& env, LazyGrid& grid, int32_t r,
                     Candidates& scratch) const {
    const CellIndex current = env.robots[static_cast<std::size_t>(r)].cell;
    if (walled_in_stays_ && grid.window_blocked(current, cfg_.scenario.params.s_range)) {
      swarmcheck::exploration::apply_decision_to_robot(cfg_, env, r,
                                                       *swarmcheck::exploration::walled_in_decision(*cfg_.rules, current));
      return 0;
    }
    int64_t newly = 0;
    swarmcheck::exploration::apply_decision_to_robot(
        cfg_, env, r, swarmcheck::exploration::decide_on_grid(cfg_, env, grid, r, scratch, newly));
    return newly;
  }
  // Runs one parallel stage (a schedule's run) with the workers kept warm around it.
  template <class Run>
  int64_t stage(Run&& run) const {
    warm_.wake();
    const int64_t sum = run();
    warm_.park(arena_.max_concurrency() - 1);
    return sum;
  }

  swarmcheck::exploration::EnvironmentConfig cfg_;
  ExplorationOptions options_;
  LazyGrid grid_;
  mutable std::vector<Candidate> scratch_;   // the sequential stage's candidates, reused
  // Whether the rule set lets a walled-in robot skip its choice (spec::walled_in_decision), and
  // the robots are dense enough for testing them to pay.
  bool walled_in_stays_;
  int32_t threads_;
  mutable tbb::task_arena arena_;
  mutable WarmWorkers warm_{arena_};   // between the parallel stages of a step (after arena_)
  // The parallel stages' schedules and per-strip candidates, reused from step to step.
  mutable BandSchedule band_;     // tried first: no waiting, for sparse robots
  // The tick of the deposits the band schedule of this step's planning also serves, if any.
  mutable std::optional<int64_t> band_for_deposit_tick_;
  mutable StripSchedule strips_;  // otherwise: waiting at the strip edges
  mutable std::vector<CellIndex> cells_;
  // A cache line each, and so is its buffer: every robot writes its candidates to its strip's.
  struct alignas(kCacheLine) StripPlanning {
    std::vector<Candidate, CacheLineAllocator<Candidate>> candidates;
  };
  mutable std::vector<StripPlanning> strip_planning_;
  mutable std::vector<char> no_scratch_;
  // Strips or one thread for a whole planning step (decisions and deposits), by timing both.
  mutable StageTuner step_tuner_;
  struct TunedStep {
    bool parallel;          // the decisions ran on the strips
    int64_t deposit_tick;   // the tick of the step's deposits
    int64_t plan_ns;        // the decisions' time
  };
  mutable std::optional<TunedStep> tuned_step_;
  // Last: its initialisation runs the deposit stage, which uses the members above.
  swarmcheck::exploration::EnvironmentState env_;
};

}  // namespace swarmcheck::impl::exploration
