#include "spec/exploration/robot.hpp"

#include "spec/util/demand.hpp"

namespace swarmcheck::exploration {

RobotConfig make_robot_config(const Scenario& s, const RobotParams& rp) {
  // Abstract mode runs no controller and no body: robots stand on their waypoints. Their records
  // then show the default controller's idle state and the start positions, whatever is chosen.
  const bool cosim = s.mode == Mode::cosim;
  return RobotConfig{&controller_of(cosim ? s.controller : ControllerKind::swarmcheck),
                     &body_of(cosim ? s.body.kind : BodyKind::kinematic), rp, ThesisControllerParams{},
                     intocps_body_model(s.body.intocps), s.params.step_size};
}

ControllerState initial_controller_of(const RobotConfig& c) {
  switch (c.controller->law) {
    case ControllerLaw::latched_two_phase: return initial_controller();
    case ControllerLaw::published_uncontroller: return initial_thesis_controller();
  }
  SWARM_DEMAND(false);
  return {};
}

BodyMemory initial_body(const RobotConfig& c, const Point_m& start) {
  BodyMemory m;
  switch (c.body->dynamics) {
    case BodyDynamics::steady_state_unicycle:
      m.pose = BodyState{start[0], start[1], 0.0};
      return m;
    case BodyDynamics::twenty_sim_rk4:
      m.intocps = intocps_body_initialised(0.0, start[0], start[1]);
      m.pose = pose_of(*m.intocps);
      return m;
  }
  SWARM_DEMAND(false);
  return m;
}

ControllerState controller_step(const RobotConfig& c, const ControllerState& s, const ControllerInputs& in) {
  switch (c.controller->law) {
    case ControllerLaw::latched_two_phase: return controller_step(c.robot, s, in);
    case ControllerLaw::published_uncontroller: return thesis_controller_step(c.thesis, s, in);
  }
  SWARM_DEMAND(false);
  return s;
}

void body_advance(const RobotConfig& c, BodyMemory& m, double servo_left, double servo_right, double t_s) {
  switch (c.body->dynamics) {
    case BodyDynamics::steady_state_unicycle:
      m.pose = body_step(c.robot, m.pose, servo_left, servo_right, c.step_s);
      return;
    case BodyDynamics::twenty_sim_rk4:
      SWARM_DEMAND(m.intocps.has_value());
      intocps_body_do_step(c.intocps, *m.intocps, servo_left, servo_right, t_s, c.step_s);
      m.pose = pose_of(*m.intocps);
      return;
  }
  SWARM_DEMAND(false);
}

void robot_step(const RobotConfig& c, ControllerState& ctrl, BodyMemory& body, const Point_m& waypoint,
                int32_t env_output, double t_s) {
  const ControllerState before = ctrl;
  ctrl = controller_step(c, before, ControllerInputs{body.pose, waypoint, env_output, c.step_s});
  body_advance(c, body, before.servo_left, before.servo_right, t_s);
}

}  // namespace swarmcheck::exploration
