#pragma once
// The onDestination handshake between the Environment and the controllers (DESIGN.md A7).
//
// Environment side (thesis tick(), exactly). `all_arrived` is the AND of every controller's
// onDestinationOutput as read this step (under the Jacobi master: as of the previous step).
//   all_arrived and flag == 1  ->  plan new waypoints;      flag := 0, onDestinationOutput := 1
//   all_arrived and flag == 0  ->  no plan;                 flag := 1, onDestinationOutput := 0
//   otherwise                  ->  no plan; nothing changes
// Initially flag = 1 and onDestinationOutput = 0.
//
// Controller side (left implicit by the thesis, made explicit here). A controller's
// onDestinationOutput is 1 while it is idle at its waypoint. When it reads the Environment's
// onDestinationOutput == 1 while idle, the waypoint it reads is new: it accepts it, lowers its
// onDestinationOutput to 0 in that same step and holds still; it raises it again on arrival.
// Under Jacobi the Environment's output is 1 for exactly one step, which every idle controller
// reads one step later, while the Environment reads their old (raised) outputs and resets its
// flag; by the time it reads again they are lowered. controller.hpp implements this side.
#include "spec/exploration/types.hpp"

namespace swarmcheck::exploration {

struct HandshakeStep {
  bool plan;
  HandshakeState next;
};

inline HandshakeState initial_handshake() { return HandshakeState{1, 0}; }

inline HandshakeStep environment_handshake(HandshakeState s, bool all_arrived) {
  if (all_arrived && s.flag == 1) return HandshakeStep{true, HandshakeState{0, 1}};
  if (all_arrived && s.flag == 0) return HandshakeStep{false, HandshakeState{1, 0}};
  return HandshakeStep{false, s};
}

}  // namespace swarmcheck::exploration
