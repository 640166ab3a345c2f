#pragma once
// The automata operations of spec/supervisor/semantics.hpp, fast: worklists over integer ids,
// an on-the-fly product that only ever builds accessible states, and a supervisor fixpoint that
// removes states incrementally. Results equal model/supervisor's state for state (same names, same
// order); the conformance harness checks that.
#include <string>
#include <vector>

#include "impl/supervisor/fsm.hpp"
#include "spec/util/budget.hpp"
#include "spec/supervisor/control.hpp"
#include "spec/supervisor/observation.hpp"
#include "spec/supervisor/semantics.hpp"
#include "swarmcheck/supervisor.hpp"

namespace swarmcheck::impl::supervisor {

// ---- budgets (spec/util/budget.hpp's WorkBudget) -----------------------------------------------
// The memory a command needs at its peak, in bytes, given the size its construction has reached
// (states and transitions, or classes and members, or pairs). A construction checks it, with the
// clock, every few thousand states; the coefficients are measured for each command as a whole
// (the process, its inputs, the construction, what is built from it afterwards), each within
// 1.3x of the peak resident memory on a large case (tests/hardening/memory_estimate_test.cpp).
// Vectors that grow by doubling peak while they move, old and new block both resident: bytes in
// them are counted at the mean of their size and their capacity (the next power of two), which
// held within 0.9-1.1x of the measured peak of products from 10^6 to 9 x 10^6 states.
struct PeakModel {
  double fixed = 0;
  double per_state = 0, per_transition = 0;               // in structures of their exact size
  double grown_per_state = 0, grown_per_transition = 0;   // in vectors that double as they grow
  double table_slot_bytes = 0;   // a power-of-two hash table at most half full: slots = bit_ceil(2 (states + 1))
  double at(double states, double transitions) const {
    return fixed + per_state * states + per_transition * transitions + grown_per_state * grown(states) +
           grown_per_transition * grown(transitions) + table_slot_bytes * power_of_two_at_least(2.0 * (states + 1.0));
  }
  static double power_of_two_at_least(double n) {
    double p = 1;
    while (p < n) p *= 2;
    return p;
  }
  static double grown(double n) { return n <= 0 ? 0 : (n + power_of_two_at_least(n)) / 2; }
};

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
Fsm product(const std::vector<const Fsm*>& parts, const std::vector<std::string>& names, WorkBudget& budget,
            const PeakModel& peak);
// The same product with its states left unnamed (fsm.state_names empty): `names` spells them
// from their tuples when they are written. It borrows the parts.
struct Product {
  Fsm fsm;
  TupleNames names;
};
Product product_with_tuples(const std::vector<const Fsm*>& parts,
                            const std::vector<std::string>& names, std::uint64_t max_bytes = 0);
// The budgeted product: every 4096 states `peak` of the states and transitions found so far is
// checked against the budget, which stops it naming `where` (default: the parts' names joined).
Product product_with_tuples(const std::vector<const Fsm*>& parts, const std::vector<std::string>& names,
                            WorkBudget& budget, const PeakModel& peak, const std::string& where = "");

bool is_controllable(const Fsm& plant, const Fsm& spec);
bool is_controllable(const Fsm& plant, const Fsm& spec, WorkBudget& budget, const PeakModel& peak);
inline constexpr EventId kNoEvent = UINT32_MAX;
// For each state z of product = plant || spec (product_with_tuples, plant first): the least
// uncontrollable event of plant (its id in plant) that plant enables at z's plant state and the
// product disables at z, or kNoEvent.
std::vector<EventId> disabled_uncontrollable(const Fsm& plant, const Product& product);
// The checks of a given supervisor (spec/supervisor/control.hpp): one product, one pass for the
// violations, one backward pass for blocking, witnesses read back along breadth-first parents.
swarmcheck::supervisor::ControlReport control_report(const Fsm& plant, const Fsm& sup);
swarmcheck::supervisor::ControlReport control_report(const Fsm& plant, const Fsm& sup, WorkBudget& budget, const PeakModel& peak);
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
// `peak` models the whole synthesis from the size of plant || spec; the time limit is also
// checked between the fixpoint's passes.
Synthesis synthesize(const Fsm& plant, const Fsm& spec, WorkBudget& budget, const PeakModel& peak);

// Partial observation (spec/supervisor/observation.hpp), state for state as the model's.
// max_bytes (0: none): the construction stops with a BudgetExceeded naming `where` (observer) or
// "plant || spec" once its estimated size passes it (the observer's subset construction can be
// exponential in the states).
Fsm observer(const Fsm& f, std::uint64_t max_bytes = 0, const std::string& where = "observer");  // f must be named
// The budgeted observer: `peak` of (classes, members of all classes) every 256 classes.
Fsm observer(const Fsm& f, WorkBudget& budget, const PeakModel& peak, const std::string& where);
swarmcheck::supervisor::ObservabilityReport observability(const Fsm& plant, const Fsm& spec);
// The budgeted check: plant || spec under `product_peak`, then the pairs of states it compares
// (quadratic in that product's states): every 4096 pairs, what the product came to plus
// `pairs_peak` of (pairs, 0).
swarmcheck::supervisor::ObservabilityReport observability(const Fsm& plant, const Fsm& spec, WorkBudget& budget,
                                                          const PeakModel& product_peak, const PeakModel& pairs_peak);
Fsm supcon_normal(const Fsm& plant, const Fsm& spec, std::uint64_t max_bytes = 0);
// The budgeted normal synthesis: plant || spec under `product`; then what it came to plus the
// observer of it under `observer` (classes, members); then what both came to plus the
// (state, class) pairs under `pairs` (pairs, their transitions); the time also between the
// fixpoint's passes. A later model counts only its own stage (and what is built after it).
struct NormalPeaks {
  PeakModel product, observer, pairs;
};
Fsm supcon_normal(const Fsm& plant, const Fsm& spec, WorkBudget& budget, const NormalPeaks& peaks);

// The check of swarmcheck::supervisor::check on the compact form.
swarmcheck::supervisor::CheckReport check(const Fsm& f);

// L(a) in L(b) and Lm(a) in Lm(b), with the spec's shortlex-least witnesses: breadth-first over
// the accessible pairs (state of a, state of b or none), each pair stored once with its parent
// and event, so memory is O(pairs) and a witness is read back along the parents.
swarmcheck::supervisor::Inclusion language_inclusion(const Fsm& a, const Fsm& b);
// Budgeted: `peak` of (pairs, 0) every 4096 pairs.
swarmcheck::supervisor::Inclusion language_inclusion(const Fsm& a, const Fsm& b, WorkBudget& budget, const PeakModel& peak);

}  // namespace swarmcheck::impl::supervisor
