#include "model/exploration/exploration_model.hpp"

#include "spec/exploration/body.hpp"
#include "spec/exploration/controller.hpp"
#include "spec/exploration/invariants.hpp"
#include "spec/util/demand.hpp"

namespace swarmcheck::exploration::model {

ExplorationModel::ExplorationModel(const Scenario& s, RobotParams rp)
    : sc_(s), rp_(rp), env_(sc_) {
  for (const Point_m& p : sc_.robots) {
    ctrl_.push_back(initial_controller());
    body_.push_back(BodyState{p[0], p[1], 0.0});
  }
}

bool ExplorationModel::done() const {
  return env_.completion_step().has_value() || env_.tick() >= sc_.max_steps;
}

void ExplorationModel::step() {
  if (sc_.mode == Mode::abstract) {
    env_.step(true);
    for (std::size_t r = 0; r < body_.size(); ++r) {
      body_[r].x_m = env_.robots()[r].waypoint[0];
      body_[r].y_m = env_.robots()[r].waypoint[1];
    }
  } else {
    // Exchange: every input is an output of the previous step.
    bool all_arrived = true;
    for (const auto& c : ctrl_) all_arrived = all_arrived && c.on_destination_output == 1;
    const std::vector<EnvRobot> env_robots = env_.robots();
    const int32_t env_output = env_.handshake().on_destination_output;
    const std::vector<ControllerState> ctrl_before = ctrl_;
    const std::vector<BodyState> body_before = body_;
    // Step every component.
    env_.step(all_arrived);
    for (std::size_t r = 0; r < ctrl_.size(); ++r)
      ctrl_[r] = controller_step(rp_, ctrl_before[r],
                                 ControllerInputs{body_before[r], env_robots[r].waypoint, env_output});
    for (std::size_t r = 0; r < body_.size(); ++r)
      body_[r] = body_step(rp_, body_before[r], ctrl_before[r].servo_left,
                           ctrl_before[r].servo_right, sc_.params.step_size);
  }
  if (sc_.rule != RuleSet::thesis) {
    const StepRecord r = record();
    SWARM_DEMAND(check_occupancy(sc_, r.robots).empty());
    SWARM_DEMAND(check_progress(sc_, r).empty());
  }
}

StepRecord ExplorationModel::record() const {
  StepRecord r;
  r.step = env_.tick();
  r.planning_steps = env_.planning_steps();
  r.handshake = env_.handshake();
  r.visited = env_.visited();
  r.free_cells = env_.free_cells();
  r.eP = env_.eP();
  r.sTime = env_.sTime();
  r.pheromone_digest = env_.pheromone_digest();
  for (std::size_t k = 0; k < body_.size(); ++k)
    r.robots.push_back(RobotRecord{env_.robots()[k].cell, env_.robots()[k].waypoint, body_[k], ctrl_[k]});
  return r;
}

}  // namespace swarmcheck::exploration::model
