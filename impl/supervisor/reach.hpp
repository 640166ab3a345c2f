#pragma once
// Backward reachability over the CSR automaton, written once for every user: coaccessibility
// (operations.hpp), the supervisor fixpoint (synth.cpp) and the mission planner's pruning of
// states that cannot reach a marked state (impl/mission/planner.cpp).
#include <cstdint>
#include <string>
#include <vector>

#include "impl/supervisor/fsm.hpp"

namespace swarmcheck::impl::supervisor {

// The reverse adjacency of an automaton as CSR: the sources of the edges into t are
// source[first[t] .. first[t + 1]), in ascending source order.
struct ReverseEdges {
  std::vector<std::uint32_t> first;  // [states + 1]
  std::vector<StateId> source;       // [edges kept]
};

// Every edge of f, or only those whose event e has (*events)[e] != 0.
ReverseEdges reverse_edges(const Fsm& f, const std::vector<std::uint8_t>* events = nullptr);

// The states from which a seed state can be reached (seeds included) by a path whose every
// state is inside `within` (all states when null); a seed outside `within` is no seed. One
// worklist pass, O(states + edges).
std::vector<std::uint8_t> coreachable(const ReverseEdges& r, const std::vector<std::uint8_t>& seeds,
                                      const std::vector<std::uint8_t>* within = nullptr);

// For an accessible automaton numbered in breadth-first order with each state's edges in event
// order (every product is): the shortlex-least word to `target`, as event ids. Breadth-first
// search met each state first from its least word, so the parent of t is the first edge into t
// in (source, event) order. O(states + edges).
std::vector<EventId> shortlex_word(const Fsm& f, StateId target);

// The names of the events of a word of f.
std::vector<std::string> event_names(const Fsm& f, const std::vector<EventId>& word);

}  // namespace swarmcheck::impl::supervisor
