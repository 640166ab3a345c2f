#pragma once
// Differential runners for the automata operations: run impl/supervisor and model/supervisor on
// the same input and describe the first difference (nothing when they agree). Automata built by
// an operation are compared up to renaming: both sides are normalised by canonical().
#include <optional>
#include <string>
#include <vector>

#include "spec/supervisor/automaton.hpp"

namespace swarmcheck::conformance::supervisor {

using spec::supervisor::Automaton;

// The automaton's accessible part with states renamed "0", "1", ... in breadth-first order from
// the initial state (events in name order), as .fsm text. Two deterministic automata have the
// same canonical text iff their accessible parts are isomorphic (same events and attributes,
// same marking, same transitions).
std::string canonical(const Automaton& a);

// The unary operations, each compared exactly (they keep the input's state names):
// accessible, coaccessible, trim, blocking states, nonblocking.
std::optional<std::string> diff_unary(const Automaton& a);
// Product of a and b (canonical), and their product in the other order (canonical up to the
// pair order of names, which the canonical form ignores).
std::optional<std::string> diff_product(const Automaton& a, const Automaton& b);
// Controllability of spec w.r.t. plant, and the supervisor (canonical).
std::optional<std::string> diff_synthesis(const Automaton& plant, const Automaton& spec);

// Writes the automata as <dir>/<stem>_<i>.fsm (the counterexample of a failed property), creating
// dir; returns the paths written.
std::vector<std::string> write_counterexample(const std::string& dir, const std::string& stem,
                                              const std::vector<Automaton>& automata);

}  // namespace swarmcheck::conformance::supervisor
