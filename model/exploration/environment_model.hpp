#pragma once
// @component Environment (reference model): the thesis's Environment FMU written the obvious
// way on a dense grid. Every cell is evaporated (or its decayed value evaluated) every step.
//   inputs:  all_arrived (AND of the controllers' onDestinationOutput, previous step)
//   state:   the grid, each robot's cell and waypoint, the handshake, progress counters
//   outputs: waypoints, onDestinationOutput, eP, sTime
//
// One step at tick t (DESIGN.md A2-A7, spec/SPEC.md):
//   1. plan?  abstract: always; cosim: environment_handshake(state, all_arrived).plan
//   2. plan:  robots in index order choose from the pheromone at t and move (occupancy changes
//             at once); each fixes its deposit centre
//   3. evaporate every cell (decay function, or the thesis's literal update)
//   4. plan:  deposits, robot by robot, around the deposit centres
//   5. tick := t + 1; eP, sTime unless completed
#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "spec/exploration/decay.hpp"
#include "spec/exploration/types.hpp"

namespace swarmcheck::exploration::model {

class EnvironmentModel {
 public:
  explicit EnvironmentModel(const Scenario& s);   // s must be valid (validate())

  // One Environment step. all_arrived is ignored in abstract mode (every step plans).
  void step(bool all_arrived);

  const std::vector<EnvRobot>& robots() const { return robots_; }
  HandshakeState handshake() const { return handshake_; }
  int64_t tick() const { return tick_; }
  int64_t planning_steps() const { return planning_steps_; }
  int64_t visited() const { return visited_; }
  int64_t free_cells() const { return free_cells_; }
  double eP() const { return eP_; }
  double sTime() const { return sTime_; }
  std::optional<int64_t> completion_step() const { return completion_step_; }

  Cell cell(CellIndex c) const;          // with the pheromone value current at tick()
  uint64_t pheromone_digest() const;     // over every cell's current value, raster order

 private:
  std::size_t index(CellIndex c) const;
  void plan();
  void plan_robot(int32_t r);
  void plan_robot_thesis(int32_t r);
  void move_robot(int32_t r, CellIndex to, bool mark);
  void evaporate();
  void deposit_around(CellIndex centre);
  void update_progress();

  Scenario sc_;
  int32_t n_;
  double ertu_dt_;            // ertu * step_size, the thesis's one factor
  DecayTable decay_;
  Eigen::ArrayXd value_;      // pheromone as written at written_[c]
  Eigen::Array<int64_t, Eigen::Dynamic, 1> written_;
  Eigen::ArrayXd current_;    // every cell's value at tick_ (dense evaluation)
  Eigen::Array<bool, Eigen::Dynamic, 1> visited_flag_;
  Eigen::Array<bool, Eigen::Dynamic, 1> obstacle_;
  Eigen::ArrayXi occupant_;   // robot index or -1
  std::vector<EnvRobot> robots_;
  std::vector<CellIndex> deposit_centre_;
  HandshakeState handshake_;
  int64_t tick_ = 0;
  int64_t planning_steps_ = 0;
  int64_t visited_ = 0;
  int64_t free_cells_ = 0;
  double eP_ = 0;
  double sTime_ = 0;
  std::optional<int64_t> completion_step_;
};

}  // namespace swarmcheck::exploration::model
