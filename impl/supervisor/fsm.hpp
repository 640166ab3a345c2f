#pragma once
// The automaton as the optimised library holds it: integer ids and compressed adjacency (CSR).
// States keep the order of the value they come from (id 0 is the initial state); events are
// numbered in name order, and each state's edges are sorted by event id, so a successor is a
// binary search over a few contiguous integers.
#include <cstdint>
#include <string>
#include <vector>

#include "spec/supervisor/automaton.hpp"

namespace swarmcheck::impl::supervisor {

using StateId = std::uint32_t;
using EventId = std::uint32_t;
inline constexpr StateId kNoState = UINT32_MAX;

struct Fsm {
  std::vector<std::string> state_names;     // [states]; 0 is initial (no states: empty automaton)
  std::vector<std::uint8_t> marked;         // [states] 1 when marked
  std::vector<std::string> event_names;     // [events], sorted
  std::vector<std::uint8_t> controllable;   // [events]
  std::vector<std::uint8_t> observable;     // [events]
  std::vector<std::uint32_t> first_edge;    // [states + 1]: edges of s are [first_edge[s], first_edge[s+1])
  std::vector<EventId> edge_event;          // [edges], ascending within a state
  std::vector<StateId> edge_target;         // [edges]

  StateId state_count() const { return static_cast<StateId>(state_names.size()); }
  EventId event_count() const { return static_cast<EventId>(event_names.size()); }
  std::size_t edge_count() const { return edge_event.size(); }
  // delta(s, e) or kNoState.
  StateId successor(StateId s, EventId e) const;
  // The id of an event name, or UINT32_MAX.
  EventId event_id(const std::string& name) const;
};

Fsm compile(const swarmcheck::supervisor::Automaton& a);
swarmcheck::supervisor::Automaton decompile(const Fsm& f);

// Builds the CSR arrays from per-state edge lists (each sorted by event). Used by operations.
void set_edges(Fsm& f, const std::vector<std::vector<std::pair<EventId, StateId>>>& edges);

// f restricted to the states with keep[s] != 0, order kept; empty when state 0 is dropped.
Fsm restrict_states(const Fsm& f, const std::vector<std::uint8_t>& keep);

}  // namespace swarmcheck::impl::supervisor
