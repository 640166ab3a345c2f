#pragma once
// A given supervisor S of a plant G (SPEC.md 13.2): the closed loop G || S, its controllability and
// its nonblocking, each with a witness when it fails.
//
//   S controllable for G  iff  no reachable state (x, y) of G || S has an uncontrollable event e
//     that G enables at x, that is an event of S, and that S disables at y.
//   Witness: the shortlex-least word s of L(G || S) (shortest, then event names compared word by
//     word) leading to such a state, and the least such e by name. Breadth-first search from the
//     initial pair, events in name order, meets the states in the shortlex order of their least
//     words, so the first violating state it meets gives exactly that word.
//   G || S nonblocking iff every reachable state reaches a marked state. Witness: the
//     shortlex-least word leading to a state that cannot.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "spec/supervisor/automaton.hpp"

namespace swarmcheck::supervisor {

struct ControlReport {
  std::size_t closed_loop_states = 0;   // reachable states of G || S
  bool controllable = true;
  std::vector<Event> witness;           // empty when controllable (or when q0 violates)
  Event disabled_event;                 // empty when controllable
  bool nonblocking = true;
  std::vector<Event> blocking_witness;  // empty when nonblocking (or when q0 blocks)
  friend bool operator==(const ControlReport&, const ControlReport&) = default;
};

// The pair (state of G, state of S) that `word` leads the closed loop to, or nothing when the
// word is not in L(G || S): each automaton moves on its own events and ignores the others.
std::optional<std::pair<State, State>> closed_loop_run(const Automaton& g, const Automaton& s,
                                                       const std::vector<Event>& word);

// Does (word, e) show S uncontrollable for G: word in L(G || S), e uncontrollable in G, enabled
// by G after it, an event of S and disabled by S after it? A replay, for checking witnesses.
bool is_uncontrollability_witness(const Automaton& g, const Automaton& s,
                                  const std::vector<Event>& word, const Event& e);

}  // namespace swarmcheck::supervisor
