#pragma once
// The reference model of system A: one Environment, one Controller and one Body per robot,
// stepped by a Jacobi fixed-step master (as INTO-CPS Maestro).
//
// Master step, x- the state before and x+ after (no component has direct feedthrough):
//   exchange:   env.all_arrived      := AND_i ctrl_i-.onDestinationOutput
//               ctrl_i.pose          := body_i-
//               ctrl_i.waypoint, .onDestinationInput := env-.waypoint_i, env-.onDestinationOutput
//               body_i.servos        := ctrl_i-.servo_left, ctrl_i-.servo_right
//   step:       env+ = env(env-, inputs); ctrl_i+ = ctrl(ctrl_i-, inputs); body_i+ = body(...)
//   advance:    steps := steps + 1
// abstract mode has no controllers or bodies: every step plans and each robot stands on its
// waypoint at once (the thesis's preliminary version).
#include <vector>

#include "model/exploration/environment_model.hpp"
#include "spec/exploration/types.hpp"

namespace swarmcheck::exploration::model {

class ExplorationModel {
 public:
  explicit ExplorationModel(const Scenario& s, RobotParams rp = RobotParams{});

  void step();
  // Completed, or max_steps steps done.
  bool done() const;
  int64_t steps() const { return env_.tick(); }
  StepRecord record() const;
  const EnvironmentModel& environment() const { return env_; }
  const Scenario& scenario() const { return sc_; }

 private:
  Scenario sc_;
  RobotParams rp_;
  EnvironmentModel env_;
  std::vector<ControllerState> ctrl_;
  std::vector<BodyState> body_;
};

}  // namespace swarmcheck::exploration::model
