#pragma once
// Partial observation (SPEC.md 13.3): events marked `uo` are not seen by a supervisor.
//
//   P            the natural projection onto the observable events: erases every `uo` event.
//   UR(X)        least Y with X in Y and ustep(Y) in Y: the states X reaches by `uo` events alone.
//   Obs(G)       the observer: its states are the nonempty sets UR(...) met by breadth-first
//                search from UR({q0}) with observable events in name order; X --e--> UR(post_e(X))
//                when post_e(X) is nonempty. Marked iff X holds a marked state. Alphabet: G's
//                observable events. The state X is named "{q,r,...}", members in G's state order
//                (so a state name containing ',' is refused: two sets could share a name).
//                L(Obs(G)) = P(L(G)) and Lm(Obs(G)) = P(Lm(G)).
//   Observable   K = L(G || S) is observable for G iff no two words s, s' of K with P(s) = P(s')
//                and a controllable e have s e in K, s' e in L(G) and s' e not in K. Searched on
//                pairs (z, z') of closed-loop states reached by such twin words: from a pair,
//                for each event in name order, an observable event moves both, an unobservable
//                one moves the first (then, separately, the second) alone. The witness is the
//                first violating pair in that breadth-first order, with its two words and the
//                least violating event.
//   Normal synthesis  SPEC.md 13.3 (model/supervisor/observation.hpp runs it): the greatest set of
//                observer classes of G || S that are free of leaks, controllable and nonblocking.
#include <optional>
#include <string>
#include <vector>

#include "spec/supervisor/automaton.hpp"

namespace swarmcheck::supervisor {

// The `uo` events of an alphabet, in name order.
std::vector<Event> unobservable_events(const std::map<Event, EventAttr>& events);

// P(word): the word without its unobservable events.
std::vector<Event> project(const Automaton& a, const std::vector<Event>& word);

// One step of UR: { delta(q, e) : q in x, e unobservable }.
StateSet unobservable_post(const Automaton& a, const StateSet& x);

// post_e(X) = { delta(q, e) : q in x } for one event.
StateSet post_event(const Automaton& a, const StateSet& x, const Event& e);

// The observer state's name, and the InputError for a state whose name contains ','.
std::string subset_name(const Automaton& a, const StateSet& x);
void refuse_commas(const Automaton& a, const std::string& what);

// The events of s that g enables at x and s disables at y (any attribute), in name order: where
// a word of the plant leaves L(G || S).
std::vector<Event> leaks(const Automaton& g, const Automaton& s, const State& x, const State& y);

// A violation of observability: after `word` the closed loop does `event` (controllable); after
// `twin`, with the same projection, the plant can do it and the closed loop cannot.
struct ObservabilityReport {
  bool observable = true;
  std::vector<Event> word, twin;
  Event event;
  friend bool operator==(const ObservabilityReport&, const ObservabilityReport&) = default;
};

// Checks a claimed violation by replaying it on the automata.
bool is_unobservability_witness(const Automaton& g, const Automaton& s,
                                const ObservabilityReport& r);

}  // namespace swarmcheck::supervisor
