#pragma once
// One robot's controller and body in the co-simulation master (SPEC.md section 7): what the
// robot stage of master_step runs for each robot, whatever its controller and body are. The rows
// of robot_kinds.hpp decide which law and which dynamics run; model/ calls these functions robot
// by robot, impl/ batches the intocps body (impl/exploration/intocps_bodies.hpp) with the same bits.
//
//   ctrl+ := controller(ctrl-, {pose-, waypoint-, env-.output, dt})
//   body+ := body(body-, ctrl-.servos) over [t, t + dt]   (t the master's clock, by repeated addition)
//   pose+ := the body's outputs (robot_x, robot_y, robot_theta)
#include <optional>

#include "spec/exploration/body.hpp"
#include "spec/exploration/body_intocps.hpp"
#include "spec/exploration/controller.hpp"
#include "spec/exploration/controller_thesis.hpp"
#include "spec/exploration/robot_kinds.hpp"
#include "spec/exploration/types.hpp"

namespace swarmcheck::exploration {

// What every robot's controller and body read: constant for a run (like mjModel).
struct RobotConfig {
  const ControllerDescriptor* controller;
  const BodyDescriptor* body;
  RobotParams robot;                    // the swarmcheck controller and the kinematic body
  ThesisControllerParams thesis;        // the thesis controller
  IntocpsBodyModel intocps;             // the intocps body
  double step_s;                        // the master's step
};
RobotConfig make_robot_config(const Scenario& s, const RobotParams& rp = RobotParams{});

// One robot's body (like mjData): the pose its controller reads, and the intocps body's whole
// memory when it has that body.
struct BodyMemory {
  BodyState pose;
  std::optional<IntocpsBodyState> intocps;
};

// At the start of a run: the controller's initial state; the body at `start` (heading 0 for the
// kinematic body, initial_position[2] for the intocps one), set up as its FMU is (the intocps
// body's outputs read 0 until its first step: body_intocps.hpp).
ControllerState initial_controller_of(const RobotConfig& c);
BodyMemory initial_body(const RobotConfig& c, const Point_m& start);

// The controller step of the row's law.
ControllerState controller_step(const RobotConfig& c, const ControllerState& s, const ControllerInputs& in);

// The body over [t_s, t_s + step_s] with the servos held, and its new pose.
void body_advance(const RobotConfig& c, BodyMemory& b, double servo_left, double servo_right, double t_s);

// Both, as the robot stage of the master: the controller from the previous outputs, the body with
// the previous servos.
void robot_step(const RobotConfig& c, ControllerState& ctrl, BodyMemory& body, const Point_m& waypoint,
                int32_t env_output, double t_s);

// The pose the intocps body's outputs give its controller.
inline BodyState pose_of(const IntocpsBodyState& b) {
  return BodyState{b.outputs.robot_x, b.outputs.robot_y, b.outputs.robot_theta};
}

}  // namespace swarmcheck::exploration
