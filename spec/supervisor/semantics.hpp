#pragma once
// The meaning of the automata operations, as one-step rules (DESIGN.md B2). Each whole operation
// is a fixpoint of one of these rules; model/supervisor iterates them the obvious way, and
// impl/supervisor must give the same automata (up to state names).
//
//   Ac(G)     least X with q0 in X and post(X) in X              (accessible states)
//   CoAc(G)   least X with Qm in X and pre(X) in X               (coaccessible states)
//   Trim(G)   G restricted to Ac(G) and CoAc(G)
//   G nonblocking   iff  Ac(G) is a subset of CoAc(G)   (every reachable state can still reach Qm)
//   G1 || G2  pairs (x1, x2) reachable by sync_successor from (q01, q02); marked iff both are
//   S controllable w.r.t. plant G  iff at every reachable (x, y) of G || S no uncontrollable event
//             enabled by G at x is an event of S that S disables at y
//   L(A) in L(B)  every word of A is a word of B; likewise Lm (see Inclusion below)
//   SupCNB(G, S)  the greatest X in Ac(G || S) whose every state is supcon_good in X and reaches
//             a marked state inside X; G || S restricted to X, then to its accessible part: the Ramadge-Wonham supremal controllable
//             nonblocking sublanguage of Lm(G) and Lm(S) (empty automaton when q0 is not kept).
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "spec/supervisor/automaton.hpp"

namespace swarmcheck::supervisor {

// ---- alphabets -----------------------------------------------------------------------------

// The union of the alphabets. An event that is controllable (or observable) in one and not in
// the other has no meaning: that throws InputError naming the event and both automata.
std::map<Event, EventAttr> alphabet_union(const Automaton& a, const std::string& a_name,
                                          const Automaton& b, const std::string& b_name);

// ---- reachability ---------------------------------------------------------------------------

StateSet post(const Automaton& a, const StateSet& x);  // { delta(q, e) : q in x }
StateSet pre(const Automaton& a, const StateSet& x);   // { q : some delta(q, e) in x }

// pre restricted to `within`: predecessors inside `within` through transitions inside it.
StateSet pre_within(const Automaton& a, const StateSet& x, const StateSet& within);

// G restricted to the states in `keep`: the order of `states` kept, transitions leaving `keep`
// dropped, the alphabet kept whole. The empty automaton when q0 is not kept.
Automaton restrict_to(const Automaton& a, const StateSet& keep);

// ---- synchronous product ---------------------------------------------------------------------

// The name of the product state (x1, x2): "x1.x2". A flat separator makes a left fold of binary
// products name states exactly as one n-ary product does: "x1.x2.x3".
State pair_name(const State& x1, const State& x2);

// The synchronous rule: a shared event moves both (or neither), a private event moves its owner.
std::optional<std::pair<State, State>> sync_successor(const Automaton& g1, const Automaton& g2,
                                                      const State& x1, const State& x2,
                                                      const Event& e);

// ---- control ----------------------------------------------------------------------------------

// The uncontrollable events enabled by plant g at x that spec s (at y) would disable.
std::vector<Event> uncontrollable_disabled(const Automaton& g, const Automaton& s, const State& x,
                                           const State& y);

// The local Ramadge-Wonham condition on product state z = (x, y) of P = G || S, for a candidate
// set X: S disables no uncontrollable event G enables at x, and each uncontrollable event G
// enables at x leads, in P, to a state of X.
bool supcon_good(const Automaton& g, const Automaton& s, const Automaton& p, const State& z,
                 const State& x, const State& y, const StateSet& candidates);

// ---- languages --------------------------------------------------------------------------------

// delta*(q0, word): the state a word leads to, or nothing when it is not in L(G).
std::optional<State> run(const Automaton& a, const std::vector<Event>& word);
bool in_closed_language(const Automaton& a, const std::vector<Event>& word);
bool in_marked_language(const Automaton& a, const std::vector<Event>& word);

// L(A) in L(B) and Lm(A) in Lm(B). When an inclusion fails, its witness is the least word of the
// difference (L(A) minus L(B), or Lm(A) minus Lm(B)) in shortlex order: shortest first, then
// event names compared word by word. A breadth-first search over the pairs (state of A, state of
// B or none), events in name order, first finds exactly that word.
struct Inclusion {
  bool closed = true;
  bool marked = true;
  std::vector<Event> closed_witness;  // empty when closed
  std::vector<Event> marked_witness;  // empty when marked
  friend bool operator==(const Inclusion&, const Inclusion&) = default;
};

}  // namespace swarmcheck::supervisor
