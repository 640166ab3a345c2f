#pragma once
// The onDestination handshake run on concrete values, through the executed code: the
// Environment through environment_handshake_rule and all_arrived_rule (or the epoch rules),
// each controller through controller_step (or epoch_controller_rule), stepped by a Jacobi or a
// Gauss-Seidel master, each robot's pose given per step (motion is the caller's). Also the two
// variants the proofs study: a controller whose output reaches the Environment one step late,
// and the epoch-numbered handshake.
//
// Ghost state tracks what the protocol must guarantee, stated here (not in spec/):
//   at waypoint   |x - xDesired| + |y - yDesired| < tolerance, from the pose
//   reached[i]    robot i has been at its waypoint since the Environment last planned
//   fresh[i]      a waypoint was issued to robot i since it last accepted one
// and a step violates
//   "no-early-plan"     if the Environment plans while some robot has not reached its waypoint
//   "fresh-acceptance"  if a controller accepts when no new waypoint was issued to it
#include <cstdint>
#include <string>
#include <vector>

#include "spec/exploration/types.hpp"

namespace swarmcheck::proofs::handshake {

// The step the controllers' outputs are held for: it sets only the servos' gains, which no
// handshake property reads.
inline constexpr double kHandshakeStep_s = 0.1;

enum class Master { jacobi, gauss_seidel };   // gauss_seidel: Environment after the controllers
enum class Protocol { flag, epoch };          // flag: the thesis's; epoch: numbered waypoints

struct Variant {
  Master master = Master::jacobi;
  Protocol protocol = Protocol::flag;
  bool late_controller = false;   // each controller's output reaches the Environment a step late
  // The proof for every number of robots (Encoding only): robot 0 stands for any one robot, robot
  // 1 for all the others, its state and port free in every step; the properties are robot 0's.
  bool representative = false;
};

const char* to_string(Master m);   // "jacobi", "gauss-seidel"

struct ControllerPort {            // what a controller shows the Environment
  bool out = true;                 // flag protocol: onDestinationOutput
  int32_t ack = 0;                 // epoch protocol: the epoch it last accepted
  bool done = true;                // epoch protocol: it has arrived at that epoch's waypoint
  bool operator==(const ControllerPort&) const = default;
};

// One robot in one step: its pose, and the waypoint the Environment issues it if it plans.
struct RobotInput {
  double x_m = 0, y_m = 0, theta_rad = 0;
  double new_x_desired_m = 0.5, new_y_desired_m = 0.5;
};

struct ConcreteState {
  exploration::HandshakeState env{1, 0};   // flag protocol
  int32_t epoch = 0;                        // epoch protocol
  std::vector<exploration::ControllerState> ctrl;   // flag protocol: the spec's controller
  std::vector<ControllerPort> internal;     // the controllers' outputs as they compute them
  std::vector<ControllerPort> port;         // as the Environment reads them (late: a step old)
  std::vector<double> x_desired_m, y_desired_m;   // each robot's current waypoint
  std::vector<bool> reached, fresh;
};

struct StepEvents {
  bool plan = false;
  std::vector<bool> accept, at_waypoint;
  std::string violated;   // "" or the property this step breaks
};

// The property's "at its waypoint": |x - xDesired| + |y - yDesired| < tolerance.
bool at_waypoint(double x_m, double y_m, double x_desired_m, double y_desired_m, double tolerance_m);

// The same for every variant: the spec's initial handshake and controllers, robots on their
// waypoints (0.5, 0.5), nothing issued.
ConcreteState initial_state(const Variant& v, int robots);

// One master step with these robot inputs, controllers with parameters rp.
StepEvents step(const Variant& v, const exploration::RobotParams& rp, ConcreteState& s,
                const std::vector<RobotInput>& in);

}  // namespace swarmcheck::proofs::handshake
