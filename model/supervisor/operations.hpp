#pragma once
// The reference model of the automata operations: each one is the fixpoint stated in
// spec/supervisor/semantics.hpp, reached the obvious way (whole-set passes until nothing
// changes). Slow and plain on purpose: it is the oracle impl/supervisor is compared against.
#include <string>
#include <utility>
#include <vector>

#include "spec/supervisor/automaton.hpp"
#include "spec/supervisor/semantics.hpp"

namespace swarmcheck::model::supervisor {

// The spec's value types, by their short names (the operations below are the model's own).
using swarmcheck::supervisor::Automaton;
using swarmcheck::supervisor::Event;
using swarmcheck::supervisor::Inclusion;
using swarmcheck::supervisor::State;
using swarmcheck::supervisor::StateSet;

StateSet accessible_states(const Automaton& a);
StateSet coaccessible_states(const Automaton& a);
Automaton accessible_part(const Automaton& a);
Automaton trim(const Automaton& a);
bool is_nonblocking(const Automaton& a);
// Accessible states that cannot reach a marked state, in the order of a.states.
std::vector<State> blocking_states(const Automaton& a);

// G1 || G2 (accessible part): states named pair_name(x1, x2), numbered in breadth-first order
// from the initial pair, events taken in name order. `origin` maps each to its pair.
struct Product {
  Automaton automaton;
  std::map<State, std::pair<State, State>> origin;
};
Product product2(const Automaton& g1, const std::string& name1, const Automaton& g2,
                 const std::string& name2);
// Left fold of product2 over the list (names for error messages); one automaton: itself.
Automaton product(const std::vector<Automaton>& parts, const std::vector<std::string>& names);

// Is Lm(S) || G controllable w.r.t. G (every reachable pair passes uncontrollable_disabled)?
bool is_controllable(const Automaton& plant, const Automaton& spec);

// The supremal controllable nonblocking supervisor of plant G for specification S.
Automaton supcon(const Automaton& plant, const Automaton& spec);

// L(A) in L(B) and Lm(A) in Lm(B), with the spec's witnesses (the shortlex-least words of the
// differences), by breadth-first search keeping each pair's whole word.
Inclusion language_inclusion(const Automaton& a, const Automaton& b);

}  // namespace swarmcheck::model::supervisor
