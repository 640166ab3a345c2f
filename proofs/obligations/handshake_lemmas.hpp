#pragma once
// The Environment's loops over the controllers, for every number of them (handshake_any_robots.cpp):
//   all_arrived_rule     (read by master_step's environment_input) is true iff every output is
//                        raised: bounded for 0..8 controllers from environment_input, and for
//                        every n by induction over the loop's body (all_arrived_step_rule)
//   epoch_environment_rule plans iff every port shows (the epoch, arrived), and then advances the
//                        epoch by one mod kEpochs: bounded for 0..8, every n by induction over
//                        epoch_ready_step_rule
// The proofs for every number of robots (the counter abstraction, the representative epoch
// proof) rest on these. Each returns nothing when it holds, else the obligation's outcome (a
// counterexample confirmed by the concrete rule, or unknown).
#include <optional>

#include "proofs/obligations/obligation.hpp"

namespace swarmcheck::proofs::handshake {

std::optional<Outcome> all_arrived_lemma(Session& session);
std::optional<Outcome> epoch_ready_lemma(Session& session);

}  // namespace swarmcheck::proofs::handshake
