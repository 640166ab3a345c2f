#pragma once
// The automaton as the optimised library holds it: integer ids and compressed adjacency (CSR).
// States keep the order of the value they come from (id 0 is the initial state); events are
// numbered in name order, and each state's edges are sorted by event id, so a successor is a
// binary search over a few contiguous integers. An operation's result may leave state_names
// empty and spell its names only when they are written (TupleNames): a product of 10^6 states
// then holds no per-state string.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "spec/supervisor/automaton.hpp"

namespace swarmcheck::impl::supervisor {

using StateId = std::uint32_t;
using EventId = std::uint32_t;
inline constexpr StateId kNoState = UINT32_MAX;

struct Fsm {
  std::vector<std::string> state_names;     // [states], or empty when spelled elsewhere (TupleNames)
  // state 0 is initial; no states: the empty automaton
  std::vector<std::uint8_t> marked;         // [states] 1 when marked
  std::vector<std::string> event_names;     // [events], sorted
  std::vector<std::uint8_t> controllable;   // [events]
  std::vector<std::uint8_t> observable;     // [events]
  std::vector<std::uint32_t> first_edge;    // [states + 1]: edges of s are [first_edge[s], first_edge[s+1])
  std::vector<EventId> edge_event;          // [edges], ascending within a state
  std::vector<StateId> edge_target;         // [edges]

  StateId state_count() const { return static_cast<StateId>(marked.size()); }
  bool named() const { return state_names.size() == marked.size(); }
  EventId event_count() const { return static_cast<EventId>(event_names.size()); }
  std::size_t edge_count() const { return edge_event.size(); }
  // delta(s, e) or kNoState.
  StateId successor(StateId s, EventId e) const;
  // The id of an event name, or UINT32_MAX.
  EventId event_id(const std::string& name) const;
};

// Appends the name of a state to a buffer: how writers spell states without storing them all.
using AppendName = std::function<void(StateId, std::string&)>;

// The names of a product's states, spelled on demand: state s stands for the tuple
// tuples[s * k .. s * k + k) of states of the k named parts, and is named "x1.x2...xk".
// The parts are borrowed: they must outlive this.
struct TupleNames {
  std::vector<const Fsm*> parts;
  std::vector<StateId> tuples;

  const StateId* tuple(StateId s) const { return tuples.data() + std::size_t{s} * parts.size(); }
  void append(StateId s, std::string& out) const;
  std::string name(StateId s) const;
};

// Spells f's own names (f.named()), or through `tuples` when given.
AppendName name_speller(const Fsm& f, const TupleNames* tuples = nullptr);
// Stores every name that `tuples` spells in f.state_names (for callers that need them all).
void store_names(Fsm& f, const TupleNames& tuples);

Fsm compile(const swarmcheck::supervisor::Automaton& a);
// f must be named.
swarmcheck::supervisor::Automaton decompile(const Fsm& f);

// Builds the CSR arrays from per-state edge lists (each sorted by event). Used by operations.
void set_edges(Fsm& f, const std::vector<std::vector<std::pair<EventId, StateId>>>& edges);

// f restricted to the states with keep[s] != 0, order kept; empty when state 0 is dropped.
// Names are kept when f has them; `old_ids`, when given, receives each kept state's id in f.
Fsm restrict_states(const Fsm& f, const std::vector<std::uint8_t>& keep,
                    std::vector<StateId>* old_ids = nullptr);

}  // namespace swarmcheck::impl::supervisor
