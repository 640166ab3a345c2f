#include "model/exploration/exploration_model.hpp"

#include "spec/exploration/body.hpp"
#include "spec/exploration/controller.hpp"
#include "spec/exploration/invariants.hpp"
#include "spec/exploration/master.hpp"
#include "spec/util/demand.hpp"

namespace swarmcheck::model::exploration {

ExplorationModel::ExplorationModel(const Scenario& s, RobotParams rp)
    : cfg_(make_environment_config(s)), rp_(rp), grid_(cfg_), env_(initial_environment(cfg_, grid_)) {
  for (const Point_m& p : s.robots) {
    ctrl_.push_back(initial_controller());
    body_.push_back(BodyState{p[0], p[1], 0.0});
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
  for (std::size_t r = 0; r < ctrl_.size(); ++r) {
    const ControllerState before = ctrl_[r];
    ctrl_[r] = controller_step(rp_, before, ControllerInputs{body_[r], env_.robots[r].waypoint, env_output});
    body_[r] = body_step(rp_, body_[r], before.servo_left, before.servo_right, cfg_.scenario.params.step_size);
  }
}

void ExplorationModel::environment_step(bool all_arrived) {
  swarmcheck::exploration::environment_step(cfg_, env_, grid_, all_arrived);
}

void ExplorationModel::place_bodies_on_waypoints() {
  for (std::size_t r = 0; r < body_.size(); ++r) {
    body_[r].x_m = env_.robots[r].waypoint[0];
    body_[r].y_m = env_.robots[r].waypoint[1];
  }
}

StepRecord ExplorationModel::record() const {
  return make_step_record(env_, pheromone_digest(cfg_, grid_, env_.tick), ctrl_, body_);
}

}  // namespace swarmcheck::model::exploration
