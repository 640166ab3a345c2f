#pragma once
// The reference model of system A: the spec's Environment step on a dense grid, one Controller
// and one Body per robot, stepped by the spec's Jacobi master (spec/exploration/master.hpp).
// Every stage is the obvious loop: robots one after another, every cell every step.
#include <optional>
#include <vector>

#include "model/exploration/dense_grid.hpp"
#include "spec/exploration/environment_step.hpp"
#include "spec/exploration/robot.hpp"
#include "spec/exploration/types.hpp"

namespace swarmcheck::model::exploration {

using namespace swarmcheck::exploration;

class ExplorationModel {
 public:
  explicit ExplorationModel(const Scenario& s, RobotParams rp = RobotParams{});   // s must be valid
  // About how many bytes a model run of `s` allocates (the memory budget's estimate).
  static std::uint64_t estimated_bytes(const Scenario& s) {
    return DenseGrid::bytes_for(s.map_size) + std::uint64_t{256} * s.robots.size();
  }
  ExplorationModel(const ExplorationModel&) = delete;   // the grid points at cfg_
  ExplorationModel& operator=(const ExplorationModel&) = delete;

  void step();
  // Completed, or max_steps steps done.
  bool done() const;

  int64_t steps() const { return env_.tick; }
  int64_t planning_steps() const { return env_.planning_steps; }
  int64_t visited() const { return env_.progress.visited; }
  int64_t free_cells() const { return env_.progress.free_cells; }
  double eP() const { return env_.progress.eP; }
  double sTime() const { return env_.progress.sTime; }
  std::optional<int64_t> completion_step() const { return env_.progress.completion_step; }
  StepRecord record() const;
  // One cell, with its pheromone current at steps().
  Cell cell(CellIndex c) const { return grid_.cell(c); }
  int64_t pheromone_written(CellIndex c) const { return grid_.written_tick(c); }
  const Scenario& scenario() const { return cfg_.scenario; }

  // The master's stages (spec/exploration/master.hpp).
  std::span<const ControllerState> controllers() const { return ctrl_; }
  int32_t environment_output() const { return env_.handshake.on_destination_output; }
  void robots_step(int32_t env_output);
  void environment_step(bool all_arrived);
  void place_bodies_on_waypoints();

 private:
  EnvironmentConfig cfg_;
  RobotConfig robot_;
  DenseGrid grid_;
  EnvironmentState env_;
  double clock_s_ = 0.0;   // the master's time, by repeated addition of the step (as INTO-CPS's engine)
  std::vector<ControllerState> ctrl_;
  std::vector<BodyMemory> body_;
};

}  // namespace swarmcheck::model::exploration
