#pragma once
// swarmcheck: the exploration library (system A). Link swarmcheck::swarmcheck.
//
//   #include <swarmcheck/exploration.hpp>
//   swarmcheck::exploration::Scenario s = swarmcheck::exploration::default_scenario();
//   swarmcheck::exploration::Exploration run(s);          // validates s; throws swarmcheck::InputError
//   (a ValidScenario, as load_valid_scenario returns, is taken as it is)
//   while (!run.done()) run.step();
//   std::printf("eP %.1f %% after %lld steps\n", run.eP(), (long long)run.steps());
//
// Same observable behaviour as the reference model, bit for bit, for every rule set and mode
// (swarmcheck's conformance harness checks it). Cost per step grows with the robots' work, not
// with the map: pheromone evaporation is evaluated lazily on the cells read or written (except
// the `thesis` rule set's literal per-step update, which is dense), and robots whose windows
// cannot interact decide in parallel with exactly the sequential result.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>

#include "spec/exploration/scenario.hpp"
#include "spec/exploration/types.hpp"
#include "spec/util/input_error.hpp"

namespace swarmcheck::exploration {

struct ExplorationOptions {
  // Threads a run may use: 0 = every core (std::thread::hardware_concurrency), 1 = this thread
  // only. Results are the same bits on any number.
  int32_t threads = 0;
  // Planning and deposits go parallel (oneTBB, over strips of the map, robots that may touch a
  // cell in common kept in index order) when a step has at least this many robots; 0: decided
  // per step from the work (robots x window cells) and the threads.
  int32_t parallel_min_robots = 0;
  // Controllers and bodies of at least this many robots step in parallel.
  int32_t parallel_min_bodies = 4096;
  // A robot with no free cell around it skips its choice (the same bits: spec::walled_in_decision)
  // when robots and obstacles are dense enough for testing every robot to pay; true: in every run
  // (the conformance harness forces it, as it forces the strips).
  bool walled_in_always = false;
};

class Exploration {
 public:
  explicit Exploration(const Scenario& s, ExplorationOptions options = {},
                       RobotParams robot = {});
  // A scenario already validated (parse_valid_scenario, load_valid_scenario): not checked again.
  explicit Exploration(const ValidScenario& s, ExplorationOptions options = {}, RobotParams robot = {});
  // About how many bytes a run of `s` allocates (the map's cells and the robots' state), for
  // refusing a scenario that cannot fit before allocating it.
  static std::uint64_t estimated_bytes(const Scenario& s);
  ~Exploration();
  Exploration(Exploration&&) noexcept;
  Exploration& operator=(Exploration&&) noexcept;

  // One master step (the Jacobi exchange in cosim mode; one planning step in abstract mode).
  void step();
  // Completed (eP reached 100) or max_steps steps done.
  bool done() const;

  int64_t steps() const;
  int64_t planning_steps() const;
  int64_t visited() const;
  int64_t free_cells() const;
  double eP() const;
  double sTime() const;
  std::optional<int64_t> completion_step() const;

  // The observable state (one trace record). O(cells) for the pheromone digest.
  StepRecord record() const;
  // Each robot's pose (metres, radians), and the cell the Environment last moved it to with the
  // waypoint it issued, by robot index: O(1), for callers that follow robots every step
  // (record() is O(cells)).
  std::span<const BodyState> bodies() const;
  std::span<const EnvRobot> robots() const;
  // One cell, with its pheromone value current at steps().
  Cell cell(CellIndex c) const;
  const Scenario& scenario() const;

 private:
  void init(const Scenario& s, ExplorationOptions options, RobotParams robot);
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace swarmcheck::exploration

namespace swarmcheck {
// The names of the first release, kept for existing callers.
using exploration::Exploration;
using exploration::ExplorationOptions;
}  // namespace swarmcheck
