#pragma once
// The automata operations of spec/supervisor/semantics.hpp, fast: worklists over integer ids,
// an on-the-fly product that only ever builds accessible states, and a supervisor fixpoint that
// removes states incrementally. Results equal model/supervisor's state for state (same names, same
// order); the conformance harness checks that.
#include <string>
#include <vector>

#include "impl/supervisor/fsm.hpp"
#include "spec/supervisor/semantics.hpp"

namespace swarmcheck::impl::supervisor {

std::vector<std::uint8_t> accessible_mask(const Fsm& f);
std::vector<std::uint8_t> coaccessible_mask(const Fsm& f);
Fsm accessible_part(const Fsm& f);
Fsm trim(const Fsm& f);
// Accessible states that cannot reach a marked state, ascending.
std::vector<StateId> blocking_states(const Fsm& f);
bool is_nonblocking(const Fsm& f);

// The synchronous product of all parts (accessible part), states named "x1.x2...", in
// breadth-first order with events in name order. `names` name the parts in error messages.
// `origin`, when given, receives each product state's tuple of component states.
// max_bytes (0: none): the product stops with a BudgetExceeded once its estimated size passes it,
// naming the states explored so far.
Fsm product(const std::vector<const Fsm*>& parts, const std::vector<std::string>& names,
            std::vector<std::vector<StateId>>* origin = nullptr, std::uint64_t max_bytes = 0);

bool is_controllable(const Fsm& plant, const Fsm& spec);
// The supremal controllable nonblocking supervisor of plant for spec.
Fsm supcon(const Fsm& plant, const Fsm& spec, std::uint64_t max_bytes = 0);

// L(a) in L(b) and Lm(a) in Lm(b), with the spec's shortlex-least witnesses: breadth-first over
// the accessible pairs (state of a, state of b or none), each pair stored once with its parent
// and event, so memory is O(pairs) and a witness is read back along the parents.
swarmcheck::supervisor::Inclusion language_inclusion(const Fsm& a, const Fsm& b);

}  // namespace swarmcheck::impl::supervisor
