#pragma once
// The automata operations of spec/supervisor/semantics.hpp, fast: worklists over integer ids,
// an on-the-fly product that only ever builds accessible states, and a supervisor fixpoint that
// removes states incrementally. Results equal model/supervisor's state for state (same names, same
// order); the conformance harness checks that.
#include <string>
#include <vector>

#include "impl/supervisor/fsm.hpp"
#include "spec/supervisor/control.hpp"
#include "spec/supervisor/observation.hpp"
#include "spec/supervisor/semantics.hpp"
#include "swarmcheck/supervisor.hpp"

namespace swarmcheck::impl::supervisor {

std::vector<std::uint8_t> accessible_mask(const Fsm& f);
std::vector<std::uint8_t> coaccessible_mask(const Fsm& f);
Fsm accessible_part(const Fsm& f);
Fsm trim(const Fsm& f);
// Accessible states that cannot reach a marked state, ascending.
std::vector<StateId> blocking_states(const Fsm& f);
bool is_nonblocking(const Fsm& f);
// Every state can reach a marked state: nonblocking, for an automaton known to be accessible (a
// product is), at half the cost of is_nonblocking.
bool every_state_coaccessible(const Fsm& f);

// The synchronous product of all parts (accessible part), states named "x1.x2...", in
// breadth-first order with events in name order. `names` name the parts in error messages.
// max_bytes (0: none): the product stops with a BudgetExceeded once its estimated size passes it,
// naming the states explored so far. The parts must be named.
Fsm product(const std::vector<const Fsm*>& parts, const std::vector<std::string>& names,
            std::uint64_t max_bytes = 0);
// The same product with its states left unnamed (fsm.state_names empty): `names` spells them
// from their tuples when they are written. It borrows the parts.
struct Product {
  Fsm fsm;
  TupleNames names;
};
Product product_with_tuples(const std::vector<const Fsm*>& parts,
                            const std::vector<std::string>& names, std::uint64_t max_bytes = 0);

bool is_controllable(const Fsm& plant, const Fsm& spec);
inline constexpr EventId kNoEvent = UINT32_MAX;
// For each state z of product = plant || spec (product_with_tuples, plant first): the least
// uncontrollable event of plant (its id in plant) that plant enables at z's plant state and the
// product disables at z, or kNoEvent.
std::vector<EventId> disabled_uncontrollable(const Fsm& plant, const Product& product);
// The checks of a given supervisor (spec/supervisor/control.hpp): one product, one pass for the
// violations, one backward pass for blocking, witnesses read back along breadth-first parents.
swarmcheck::supervisor::ControlReport control_report(const Fsm& plant, const Fsm& sup);
// The supremal controllable nonblocking supervisor of plant for spec.
Fsm supcon(const Fsm& plant, const Fsm& spec, std::uint64_t max_bytes = 0);
// The same supervisor with its states left unnamed (spelled by `names` from (plant, spec) pairs;
// plant and spec are borrowed), and whether spec is controllable for plant: both from one
// product, for callers that need both or cannot afford a string per state.
struct Synthesis {
  Fsm supervisor;
  TupleNames names;
  bool spec_controllable = true;
};
Synthesis synthesize(const Fsm& plant, const Fsm& spec, std::uint64_t max_bytes = 0);

// Partial observation (spec/supervisor/observation.hpp), state for state as the model's.
// max_bytes (0: none): the construction stops with a BudgetExceeded naming `where` (observer) or
// "plant || spec" once its estimated size passes it (the observer's subset construction can be
// exponential in the states).
Fsm observer(const Fsm& f, std::uint64_t max_bytes = 0, const std::string& where = "observer");  // f must be named
swarmcheck::supervisor::ObservabilityReport observability(const Fsm& plant, const Fsm& spec);
Fsm supcon_normal(const Fsm& plant, const Fsm& spec, std::uint64_t max_bytes = 0);

// The check of swarmcheck::supervisor::check on the compact form.
swarmcheck::supervisor::CheckReport check(const Fsm& f);

// L(a) in L(b) and Lm(a) in Lm(b), with the spec's shortlex-least witnesses: breadth-first over
// the accessible pairs (state of a, state of b or none), each pair stored once with its parent
// and event, so memory is O(pairs) and a witness is read back along the parents.
swarmcheck::supervisor::Inclusion language_inclusion(const Fsm& a, const Fsm& b);

}  // namespace swarmcheck::impl::supervisor
