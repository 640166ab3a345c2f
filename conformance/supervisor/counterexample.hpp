#pragma once
// The counterexample writer of the automata campaign: a failed property's (shrunk) automata as
// .fsm files that `swarmcheck fsm ...` reads back, to replay the difference by hand.
#include <string>
#include <vector>

#include "spec/supervisor/automaton.hpp"

namespace swarmcheck::conformance::supervisor {

// Writes the automata as <dir>/<stem>_<i>.fsm (each whole or not at all), creating dir; returns
// the paths written, in order.
std::vector<std::string> write_counterexample(const std::string& dir, const std::string& stem,
                                              const std::vector<swarmcheck::supervisor::Automaton>& automata);

}  // namespace swarmcheck::conformance::supervisor
