#include "fmi/fmu/ports.hpp"

#include <optional>
#include <string_view>
#include <utility>

#include "fmi/fmu/variable_table.hpp"

namespace swarmcheck::fmi {

std::string index_name(const std::string& member, int32_t k) {
  const std::size_t at = member.find("__");
  if (at != std::string::npos) return member.substr(0, at) + std::to_string(k) + member.substr(at + 2);
  return member + std::to_string(k);
}

std::string describe(std::string_view kind, const std::string& member, std::optional<int32_t> k) {
  // By kind, then member; in a repeated group's text '#' stands for the robot's or obstacle's
  // number, so that no two variables of an FMU share a description.
  struct Text {
    std::string_view kind, member;
    const char* text;
  };
  static constexpr Text kDescriptions[] = {
      {"environment", "nRobots", "number of robots (fixed at export)"},
      {"environment", "nObstacles", "number of obstacle cells (fixed at export)"},
      {"environment", "mapSize", "map side length, cells"},
      {"environment", "cellSize", "cell side, m"},
      {"environment", "step_size",
       "Environment step, s (doStep takes a step within 1e-9 of a whole multiple of it, as that many steps)"},
      {"environment", "s_range", "sensing and spraying range, cells (Chebyshev)"},
      {"environment", "a1", "deposit decay length, cells"},
      {"environment", "a2", "divisor of the uniform deposit term"},
      {"environment", "epsilon", "uniform deposit numerator"},
      {"environment", "ertu_perc", "evaporation rate, 1/s"},
      {"environment", "eta", "heuristic factor"},
      {"environment", "max_ph", "peak deposit"},
      {"environment", "phi", "pheromone exponent"},
      {"environment", "lambda", "heuristic exponent"},
      {"environment", "rule", "rule set: 0 thesis, 1 deterministic, 2 stochastic"},
      {"environment", "seed", "the run's seed (stochastic rule)"},
      {"environment", "handshake", "the Environment's handshake: 0 the thesis's onDestination flags, 1 epoch-numbered"},
      {"environment", "onDestinationOutput", "1: new waypoints were issued in this step (the controllers accept them)"},
      {"environment", "eP", "map exploration percentage"},
      {"environment", "sTime", "simulated time, s"},
      {"environment", "epoch", "epoch of the last plan (epoch handshake), mod 4"},
      {"environment", "planningSteps", "steps in which new waypoints were issued"},
      {"environment", "stepCount", "Environment steps done"},
      {"environment", "flag", "the thesis's handshake flag"},
      {"environment", "port", "the thesis's live-view port (accepted; swarmcheck's Environment opens no socket)"},
      {"environment", "lx_", "start x of robot #, m"},
      {"environment", "ly_", "start y of robot #, m"},
      {"environment", "x_", "x of robot #, m (recorded; the Environment plans on its own cells)"},
      {"environment", "y_", "y of robot #, m (recorded)"},
      {"environment", "onDestination__Input", "1: robot #'s controller is idle at its waypoint"},
      {"environment", "epochAck", "the epoch robot #'s controller last accepted (epoch handshake)"},
      {"environment", "xDesired", "x of robot #'s waypoint, m"},
      {"environment", "yDesired", "y of robot #'s waypoint, m"},
      {"environment", "ox_", "obstacle cell #, first index"},
      {"environment", "oy_", "obstacle cell #, second index"},
      {"controller", "k_beta", "rotation gain"},
      {"controller", "k_v", "linear gain"},
      {"controller", "handshake", "the controller's handshake: 0 the thesis's onDestination flags, 1 epoch-numbered"},
      {"controller", "x", "x of the robot, m (the Body's robot_x)"},
      {"controller", "y", "y of the robot, m (the Body's robot_y)"},
      {"controller", "phi", "heading of the robot, rad (the Body's robot_theta)"},
      {"controller", "xDesired", "x of the waypoint, m"},
      {"controller", "yDesired", "y of the waypoint, m"},
      {"controller", "onDestinationInput", "the Environment's onDestinationOutput: 1 when it issued new waypoints"},
      {"controller", "epochInput", "the Environment's epoch (epoch handshake)"},
      {"controller", "servoLeft", "left servo command in [-1, 1]"},
      {"controller", "servoRight", "right servo command in [-1, 1]"},
      {"controller", "onDestinationOutput", "1: the robot is at its waypoint and idle"},
      {"controller", "epochAck", "the epoch of the waypoint last accepted (epoch handshake)"},
      {"controller", "accepted", "waypoints accepted so far"},
      {"controller", "beta", "error on the robot orientation, rad"},
      {"controller", "rho", "distance to the waypoint, m"},
      {"controller", "v", "linear speed command"},
      {"controller", "w", "angular speed command"},
      {"controller", "maneuver", "1 orient, 2 drive"},
      {"controller", "target", "the heading maneuver 1 turns to, rad (chosen when it began)"},
      {"body", "x0", "start x, m"},
      {"body", "y0", "start y, m"},
      {"body", "theta0", "start heading, rad (forward is (-sin theta, cos theta))"},
      {"body", "wheel_radius", "wheel radius r, m"},
      {"body", "motor_gain", "wheel speed per unit servo command K, rad/s"},
      {"body", "half_axle", "half the distance between the wheels a, m"},
      {"body", "servo_left_input", "left servo command"},
      {"body", "servo_right_input", "right servo command"},
      {"body", "robot_x", "x, m"},
      {"body", "robot_y", "y, m"},
      {"body", "robot_theta", "heading theta, rad"},
      // The thesis interface's Environment: its own where the meaning differs, else the Environment's.
      {"thesis environment", "nRobots", "robots taking part: the first nRobots (at most this FMU's robots)"},
      {"thesis environment", "nObstacles", "obstacle cells taking part: the first nObstacles (at most this FMU's slots)"},
      {"thesis environment", "flag", "the thesis's handshake flag at start (swarmcheck's Environment: 1)"},
      {"thesis environment", "stepCount", "the thesis's step counter at start (swarmcheck's Environment: 0)"},
      {"thesis environment", "onDestinationOutput", "1.0: new waypoints were issued in this step (the controllers accept them)"},
      {"thesis environment", "onDestination__Input", "1.0: robot #'s controller is idle at its waypoint"},
      {"thesis controller", "maneuver", "1 orient, 2 drive: the start maneuver (2, as the thesis's init() sets it), then the current"},
      {"thesis controller", "beta", "error on the robot orientation, rad: at start, then the current"},
      {"thesis controller", "rho", "distance to the waypoint, m (of the last step)"},
      {"thesis controller", "v", "linear speed command (of the last step)"},
      {"thesis controller", "w", "angular speed command (of the last step)"},
      {"thesis controller", "onDestinationInput", "the Environment's onDestinationOutput: 1.0 when it issued new waypoints"},
      {"thesis controller", "onDestinationOutput", "1.0: the robot is at its waypoint and idle"},
  };
  const auto find = [&](std::string_view in) -> const Text* {
    for (const Text& d : kDescriptions)
      if (d.kind == in && d.member == member) return &d;
    return nullptr;
  };
  const Text* d = find(kind);
  if (!d && kind.rfind("thesis ", 0) == 0) d = find(kind.substr(7));
  if (!d) return "";
  std::string text = d->text;
  const std::size_t at = text.find('#');
  if (at != std::string::npos) text.replace(at, 1, k ? std::to_string(*k) : std::string("k"));
  return text;
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

void VariableTable::bind_named(double& value, std::string name, Role role, std::string description) {
  Variable v;
  v.name = std::move(name);
  v.value_reference = static_cast<uint32_t>(vars_.size());
  v.type = BaseType::real;
  v.real = &value;
  attributes(v, role);
  description_.push_back(std::move(description));
  slots_.push_back(Slot{&value, v.type, v.causality});
  vars_.push_back(std::move(v));
}

const Variable* VariableTable::find(const std::string& name) const {
  for (const Variable& v : vars_)
    if (v.name == name) return &v;
  return nullptr;
}

}  // namespace swarmcheck::fmi
