#pragma once
// The onDestination handshake run on concrete values: the Environment through the spec's
// environment_handshake, each controller through the spec's controller_step (a robot either
// stands on its waypoint or 3 m away, as the arrival input says), stepped by a Jacobi or a
// Gauss-Seidel master. Also the two variants the proofs study: a controller whose output
// reaches the Environment one step late, and the epoch-numbered handshake.
//
// Ghost state tracks what the protocol must guarantee:
//   reached[i]  robot i stands on the last waypoint the Environment issued to it
//   fresh[i]    a waypoint was issued to robot i since it last accepted one
// and a step violates
//   "no-early-plan"     if the Environment plans while some robot has not reached its waypoint
//   "fresh-acceptance"  if a controller accepts when no new waypoint was issued to it
#include <cstdint>
#include <string>
#include <vector>

#include "spec/exploration/types.hpp"

namespace swarmcheck::proofs::handshake {

enum class Master { jacobi, gauss_seidel };   // gauss_seidel: Environment after the controllers
enum class Protocol { flag, epoch };          // flag: the thesis's; epoch: numbered waypoints

struct Variant {
  Master master = Master::jacobi;
  Protocol protocol = Protocol::flag;
  bool late_controller = false;   // each controller's output reaches the Environment a step late
};

const char* to_string(Master m);   // "jacobi", "gauss-seidel"

constexpr int32_t kEpochs = 4;     // epochs are counted modulo 4 (2 bits)

struct ControllerPort {            // what a controller shows the Environment
  bool out = true;                 // flag protocol: onDestinationOutput
  int32_t ack = 0;                 // epoch protocol: the epoch it last accepted
  bool done = true;                // epoch protocol: it has arrived at that epoch's waypoint
  bool operator==(const ControllerPort&) const = default;
};

struct ConcreteState {
  exploration::HandshakeState env{1, 0};   // flag protocol
  int32_t epoch = 0;                        // epoch protocol
  std::vector<exploration::ControllerState> ctrl;   // flag protocol: the spec's controller
  std::vector<ControllerPort> internal;     // the controllers' outputs as they compute them
  std::vector<ControllerPort> port;         // as the Environment reads them (late: a step old)
  std::vector<bool> reached, fresh;
};

struct StepEvents {
  bool plan = false;
  std::vector<bool> accept, arrive;
  std::string violated;   // "" or the property this step breaks
};

// The same for every variant: the spec's initial handshake and controllers, robots on their
// waypoints, nothing issued.
ConcreteState initial_state(const Variant& v, int robots);

// One master step with these arrival inputs (arrival[i]: robot i stands on its waypoint).
StepEvents step(const Variant& v, ConcreteState& s, const std::vector<bool>& arrival);

}  // namespace swarmcheck::proofs::handshake
