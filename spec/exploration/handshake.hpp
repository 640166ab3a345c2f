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
//
// The epoch-numbered handshake (not in the thesis; proofs/ shows it survives the orderings the
// flag handshake does not): the Environment shows an epoch (mod kEpochs); it plans when every
// controller shows (its epoch = the Environment's, arrived), then increments the epoch; a
// controller accepts when it reads an epoch other than the one it last accepted, and shows
// arrived once its robot is at the waypoint (arrived_rule).
//
// Each rule is written once over a domain D (spec/util/num.hpp) and instantiated in
// handshake.cpp for num::Concrete (what runs) and num::Symbolic (what proofs/ proves).
#include <functional>
#include <span>

#include "spec/exploration/types.hpp"
#include "spec/util/num.hpp"

namespace swarmcheck::exploration {

inline constexpr int32_t kEpochs = 4;

template <class D>
struct HandshakeStateT {
  typename D::Bool flag, output;   // flag == 1, onDestinationOutput == 1
};

template <class D>
struct HandshakeStepT {
  typename D::Bool plan;
  HandshakeStateT<D> next;
};

template <class D>
HandshakeStepT<D> environment_handshake_rule(const HandshakeStateT<D>& s, const typename D::Bool& all_arrived);

// Stage 1 of the Environment's step (environment_step.hpp): whether it plans, the handshake
// state advanced by environment_handshake_rule; in abstract mode every step plans.
template <class D>
typename D::Bool handshake_stage_rule(Mode mode, HandshakeStateT<D>& s, const typename D::Bool& all_arrived);

// all_arrived_rule's loop body: the conjunction so far and controller k's output.
template <class D>
typename D::Bool all_arrived_step_rule(const typename D::Bool& all, const typename D::Bool& output);

// The Environment's planning input: every controller's onDestinationOutput is 1, for n
// controllers whose outputs output_of(k) gives (no copy of them on the master's hot path). The
// one function the master (model and impl) and the proofs call.
template <class D>
typename D::Bool all_arrived_rule(std::size_t n, const std::function<typename D::Bool(std::size_t)>& output_of);

template <class D>
struct EpochStepT {
  typename D::Bool plan;
  typename D::Int epoch;   // the Environment's epoch after the step
};

// epoch_environment_rule's loop body: ready so far, and controller k shows (epoch, arrived).
template <class D>
typename D::Bool epoch_ready_step_rule(const typename D::Bool& ready, const typename D::Int& epoch,
                                       const typename D::Int& ack, const typename D::Bool& done);

// The Environment's next epoch after a plan: epoch + 1 mod kEpochs.
template <class D>
typename D::Int next_epoch_rule(const typename D::Int& epoch);

template <class D>
EpochStepT<D> epoch_environment_rule(const typename D::Int& epoch, std::span<const typename D::Int> acks,
                                     std::span<const typename D::Bool> done);

// What an epoch controller shows the Environment (FMI: epochAck and onDestinationOutput).
template <class D>
struct EpochPortT {
  typename D::Int ack;
  typename D::Bool done;
};

template <class D>
struct EpochControllerT {
  typename D::Int ack;     // the epoch it last accepted
  typename D::Bool done;   // its robot has reached that epoch's waypoint
};

// One epoch controller step: reads the Environment's epoch and whether its robot is at its
// waypoint now; `accepted` is set when it takes a new waypoint.
template <class D>
EpochControllerT<D> epoch_controller_rule(const EpochControllerT<D>& s, const typename D::Int& env_epoch,
                                          const typename D::Bool& at_waypoint);

// ---- The concrete API. ----

struct HandshakeStep {
  bool plan;
  HandshakeState next;
};

inline HandshakeState initial_handshake() { return HandshakeState{1, 0}; }

HandshakeStep environment_handshake(HandshakeState s, bool all_arrived);

// handshake_stage_rule on the concrete state: whether the step plans; advances s in cosim mode.
bool handshake_stage(Mode mode, HandshakeState& s, bool all_arrived);

}  // namespace swarmcheck::exploration
