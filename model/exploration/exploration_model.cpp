#include "model/exploration/exploration_model.hpp"

#include "spec/exploration/invariants.hpp"
#include "spec/exploration/master.hpp"
#include "spec/util/demand.hpp"

namespace swarmcheck::model::exploration {

ExplorationModel::ExplorationModel(const Scenario& s, RobotParams rp)
    : cfg_(make_environment_config(s)), robot_(make_robot_config(s, rp)), grid_(cfg_),
      env_(initial_environment(cfg_, grid_)) {
  for (const Point_m& p : s.robots) {
    ctrl_.push_back(initial_controller_of(robot_));
    body_.push_back(initial_body(robot_, p));
  }
}

bool ExplorationModel::done() const {
  return env_.progress.completion_step.has_value() || env_.tick >= cfg_.scenario.max_steps;
}

void ExplorationModel::step() {
  master_step(cfg_.scenario.mode, *this);
  if (cfg_.rules->keeps_occupancy_invariants) {
    const StepRecord r = record();
    SWARM_DEMAND(check_occupancy(cfg_.scenario, r.robots).empty());
    SWARM_DEMAND(check_progress(cfg_.scenario, r).empty());
  }
}

void ExplorationModel::robots_step(int32_t env_output) {
  for (std::size_t r = 0; r < ctrl_.size(); ++r)
    robot_step(robot_, ctrl_[r], body_[r], env_.robots[r].waypoint, env_output, clock_s_);
  clock_s_ = clock_s_ + cfg_.scenario.params.step_size;
}

void ExplorationModel::environment_step(bool all_arrived) {
  swarmcheck::exploration::environment_step(cfg_, env_, grid_, all_arrived);
}

void ExplorationModel::place_bodies_on_waypoints() {
  for (std::size_t r = 0; r < body_.size(); ++r) {
    body_[r].pose.x_m = env_.robots[r].waypoint[0];
    body_[r].pose.y_m = env_.robots[r].waypoint[1];
  }
}

StepRecord ExplorationModel::record() const {
  std::vector<BodyState> poses;
  std::vector<IntocpsBodyState> intocps;
  for (const BodyMemory& b : body_) {
    poses.push_back(b.pose);
    if (b.intocps) intocps.push_back(*b.intocps);
  }
  return make_step_record(env_, pheromone_digest(cfg_, grid_, env_.tick), ctrl_, poses, intocps);
}

}  // namespace swarmcheck::model::exploration
