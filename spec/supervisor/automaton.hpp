#pragma once
// A deterministic finite automaton over named events, as a plain value (DESIGN.md B2).
//
//   G = (Q, Sigma, delta, q0, Qm)
//   Q      states            `states`, in order; states[0] is the initial state q0.
//                            An automaton with no states is the empty automaton (empty language).
//   Sigma  events            `events`, each with controllable / observable attributes.
//   delta  transitions       `delta[q][e] = q'`: a partial *function*, so G is deterministic.
//   Qm     marked states     `marked`.
//
// Languages: L(G) = { s | delta*(q0, s) defined }, Lm(G) = { s | delta*(q0, s) in Qm }.
// Maps (not hash maps) keep every iteration order, and so every output, deterministic.
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace swarmcheck::supervisor {

struct EventAttr {
  bool controllable = true;  // UMDES default when a file omits the attribute: c
  bool observable = true;    // UMDES default: o
  friend bool operator==(const EventAttr&, const EventAttr&) = default;
};

using State = std::string;
using Event = std::string;
using StateSet = std::set<State>;

struct Automaton {
  std::vector<State> states;                        // states[0] is initial
  std::set<State> marked;                           // subset of states
  std::map<Event, EventAttr> events;                // the alphabet Sigma
  std::map<State, std::map<Event, State>> delta;    // delta[q][e] = q'

  friend bool operator==(const Automaton&, const Automaton&) = default;
};

// q0, or nothing for the empty automaton.
std::optional<State> initial_state(const Automaton& a);

// delta(q, e), or nothing when e is not enabled at q.
std::optional<State> successor(const Automaton& a, const State& q, const Event& e);

// The events enabled at q, in name order.
std::vector<Event> enabled(const Automaton& a, const State& q);

std::size_t transition_count(const Automaton& a);

// Every structural invariant of the value (names unique, marked and delta over known states and
// events): the empty string when it holds, else the first broken one in words. Readers and
// operations must only ever produce well-formed automata.
std::string well_formedness_error(const Automaton& a);

}  // namespace swarmcheck::supervisor
