#include "fmi/fmu/ports.hpp"

#include <string_view>
#include <utility>

#include "fmi/fmu/variable_table.hpp"

namespace swarmcheck::fmi {

std::string index_name(const std::string& member, int32_t k) {
  const std::size_t at = member.find("__");
  if (at != std::string::npos) return member.substr(0, at) + std::to_string(k) + member.substr(at + 2);
  return member + std::to_string(k);
}

const char* describe(const std::string& member) {
  static constexpr std::pair<std::string_view, const char*> kDescriptions[] = {
      {"nRobots", "number of robots (fixed at export)"},
      {"nObstacles", "number of obstacle cells (fixed at export)"},
      {"mapSize", "map side length, cells"},
      {"cellSize", "cell side, m"},
      {"step_size", "co-simulation step, s (doStep accepts this step only)"},
      {"s_range", "sensing and spraying range, cells (Chebyshev)"},
      {"a1", "deposit decay length, cells"},
      {"a2", "divisor of the uniform deposit term"},
      {"epsilon", "uniform deposit numerator"},
      {"ertu_perc", "evaporation rate, 1/s"},
      {"eta", "heuristic factor"},
      {"max_ph", "peak deposit"},
      {"phi", "pheromone exponent (Environment); robot heading, rad (Controller input)"},
      {"lambda", "heuristic exponent"},
      {"rule", "rule set: 0 thesis, 1 deterministic, 2 stochastic"},
      {"seed", "the run's seed (stochastic rule)"},
      {"handshake", "0: the thesis's onDestination flag handshake, 1: the epoch-numbered handshake"},
      {"onDestinationOutput", "used for synchronization"},
      {"eP", "map exploration percentage"},
      {"sTime", "simulated time, s"},
      {"epoch", "epoch of the last plan (epoch handshake), mod 4"},
      {"planningSteps", "steps in which new waypoints were issued"},
      {"stepCount", "co-simulation steps done"},
      {"flag", "the thesis's handshake flag"},
      {"lx_", "start x of the robot, m"},
      {"ly_", "start y of the robot, m"},
      {"x_", "x of the robot, m (recorded; the Environment plans on its own cells)"},
      {"y_", "y of the robot, m (recorded)"},
      {"onDestination__Input", "the robot's controller is idle at its waypoint"},
      {"epochAck", "the epoch the controller last accepted (epoch handshake)"},
      {"xDesired", "x of the robot's waypoint, m"},
      {"yDesired", "y of the robot's waypoint, m"},
      {"ox_", "obstacle cell, first index"},
      {"oy_", "obstacle cell, second index"},
      {"k_beta", "rotation gain"},
      {"k_v", "linear gain"},
      {"x", "x robot coordinate, m"},
      {"y", "y robot coordinate, m"},
      {"onDestinationInput", "the Environment's onDestinationOutput"},
      {"epochInput", "the Environment's epoch (epoch handshake)"},
      {"servoLeft", "left servo command in [-1, 1]"},
      {"servoRight", "right servo command in [-1, 1]"},
      {"accepted", "waypoints accepted so far"},
      {"beta", "error on the robot orientation, rad"},
      {"rho", "distance to the waypoint, m"},
      {"v", "linear speed command"},
      {"w", "angular speed command"},
      {"maneuver", "1 orient, 2 drive"},
      {"target", "the heading maneuver 1 turns to, rad (chosen when it began)"},
      {"x0", "start x, m"},
      {"y0", "start y, m"},
      {"theta0", "start heading, rad (forward is (-sin theta, cos theta))"},
      {"wheel_radius", "wheel radius r, m"},
      {"motor_gain", "wheel speed per unit servo command K, rad/s"},
      {"half_axle", "half the distance between the wheels a, m"},
      {"servo_left_input", "left servo command"},
      {"servo_right_input", "right servo command"},
      {"robot_x", "x, m"},
      {"robot_y", "y, m"},
      {"robot_theta", "heading theta, rad"},
  };
  for (const auto& [name, text] : kDescriptions)
    if (name == member) return text;
  return "";
}

const char* to_string(BaseType t) { return t == BaseType::real ? "Real" : "Integer"; }
const char* to_string(Causality c) {
  switch (c) {
    case Causality::parameter: return "parameter";
    case Causality::input: return "input";
    case Causality::output: return "output";
    case Causality::local: return "local";
  }
  return "local";
}
const char* to_string(Variability v) {
  switch (v) {
    case Variability::constant: return "constant";
    case Variability::fixed: return "fixed";
    case Variability::discrete: return "discrete";
    case Variability::continuous: return "continuous";
  }
  return "continuous";
}
const char* to_string(Initial i) {
  switch (i) {
    case Initial::none: return "";
    case Initial::exact: return "exact";
    case Initial::calculated: return "calculated";
  }
  return "";
}

void VariableTable::attributes(Variable& v, Role role) {
  const Variability changing = v.type == BaseType::real ? Variability::continuous : Variability::discrete;
  switch (role) {
    case Role::parameter:
      v.causality = Causality::parameter, v.variability = Variability::fixed, v.initial = Initial::exact;
      break;
    case Role::constant:
      v.causality = Causality::local, v.variability = Variability::constant, v.initial = Initial::exact;
      break;
    case Role::input:
      v.causality = Causality::input, v.variability = changing, v.initial = Initial::none;
      break;
    case Role::output:
      v.causality = Causality::output, v.variability = changing, v.initial = Initial::calculated;
      break;
    case Role::local:
      v.causality = Causality::local, v.variability = changing, v.initial = Initial::calculated;
      break;
  }
}

const Variable* VariableTable::find(const std::string& name) const {
  for (const Variable& v : vars_)
    if (v.name == name) return &v;
  return nullptr;
}

}  // namespace swarmcheck::fmi
