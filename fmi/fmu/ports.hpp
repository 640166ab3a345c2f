#pragma once
// The FMUs' variables, declared once: each struct below is one group of variables of one
// causality, and the FMI variable list (names, value references, types, causality, variability,
// initial), the model description and the fmi2Get/Set bindings are all derived from these
// declarations (variable_table.hpp). Names are the thesis's (its Tables 2 and 3, and the INTO-CPS
// line follower's Body_Block); groups marked per robot or per obstacle are repeated for robots
// 1..N and obstacles 1..M, fixed when the FMU is exported, and their members are named by
// index_name(): the number goes where the member name has a double underscore, or at its end
// (x_ -> x_1, xDesired -> xDesired1, onDestination__Input -> onDestination1Input).
//
// Value references: the groups of an FMU in the order its Component binds them (scalar groups
// first, then robot 1's groups, robot 2's, ..., then the obstacles'), members in declaration
// order, numbered from 0. So a variable's reference depends only on these declarations and N, M.
#include <boost/hana.hpp>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace swarmcheck::fmi {

// ---- Environment (thesis Environment FMU, definitive version) ----
struct EnvironmentConstants {   // causality local, variability constant
  BOOST_HANA_DEFINE_STRUCT(EnvironmentConstants, (int32_t, nRobots), (int32_t, nObstacles));
};
struct EnvironmentParameters {   // causality parameter, variability fixed
  BOOST_HANA_DEFINE_STRUCT(EnvironmentParameters,
      (int32_t, mapSize), (double, cellSize), (double, step_size), (int32_t, s_range), (double, a1), (double, a2),
      (double, epsilon), (double, ertu_perc), (double, eta), (double, max_ph), (double, phi), (double, lambda),
      (int32_t, rule), (int32_t, seed), (int32_t, handshake));
};
struct EnvironmentOutputs {
  BOOST_HANA_DEFINE_STRUCT(EnvironmentOutputs,
      (int32_t, onDestinationOutput), (double, eP), (double, sTime), (int32_t, epoch), (int32_t, planningSteps));
};
struct EnvironmentLocals {
  BOOST_HANA_DEFINE_STRUCT(EnvironmentLocals, (int32_t, stepCount), (int32_t, flag));
};
struct EnvironmentRobotParameters {   // per robot: the start position (thesis lx_i, ly_i)
  BOOST_HANA_DEFINE_STRUCT(EnvironmentRobotParameters, (double, lx_), (double, ly_));
};
struct EnvironmentRobotInputs {   // per robot
  BOOST_HANA_DEFINE_STRUCT(EnvironmentRobotInputs,
      (double, x_), (double, y_), (int32_t, onDestination__Input), (int32_t, epochAck));
};
struct EnvironmentRobotOutputs {   // per robot
  BOOST_HANA_DEFINE_STRUCT(EnvironmentRobotOutputs, (double, xDesired), (double, yDesired));
};
struct EnvironmentObstacleParameters {   // per obstacle: its cell (thesis ox_k, oy_k)
  BOOST_HANA_DEFINE_STRUCT(EnvironmentObstacleParameters, (int32_t, ox_), (int32_t, oy_));
};

// ---- Controller (thesis Controller FMU) ----
struct ControllerParameters {
  BOOST_HANA_DEFINE_STRUCT(ControllerParameters, (double, k_beta), (double, k_v), (int32_t, handshake));
};
struct ControllerInputs {
  BOOST_HANA_DEFINE_STRUCT(ControllerInputs,
      (double, x), (double, y), (double, phi), (double, xDesired), (double, yDesired),
      (int32_t, onDestinationInput), (int32_t, epochInput));
};
struct ControllerOutputs {
  BOOST_HANA_DEFINE_STRUCT(ControllerOutputs,
      (double, servoLeft), (double, servoRight), (int32_t, onDestinationOutput), (int32_t, epochAck),
      (int32_t, accepted));
};
struct ControllerLocalVariables {
  BOOST_HANA_DEFINE_STRUCT(ControllerLocalVariables,
      (double, beta), (double, rho), (double, v), (double, w), (int32_t, maneuver), (double, target));
};

// ---- Body (INTO-CPS line follower Body_Block, steady state; spec/exploration/body.hpp) ----
struct BodyParameters {
  BOOST_HANA_DEFINE_STRUCT(BodyParameters,
      (double, x0), (double, y0), (double, theta0), (double, wheel_radius), (double, motor_gain),
      (double, half_axle));
};
struct BodyInputs {
  BOOST_HANA_DEFINE_STRUCT(BodyInputs, (double, servo_left_input), (double, servo_right_input));
};
struct BodyOutputs {
  BOOST_HANA_DEFINE_STRUCT(BodyOutputs, (double, robot_x), (double, robot_y), (double, robot_theta));
};

// A group member's name for robot or obstacle number k (1-based); see the header comment.
std::string index_name(const std::string& member, int32_t k);
// The description written in the model description of an FMU of `kind` ("environment",
// "controller", "body") for a group member, robot or obstacle k's in a repeated group (empty if
// none). No two variables of an FMU share one; a name in two FMUs has its meaning in each.
std::string describe(std::string_view kind, const std::string& member, std::optional<int32_t> k);

}  // namespace swarmcheck::fmi
