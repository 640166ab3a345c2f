#include "spec/supervisor/control.hpp"

#include "spec/supervisor/semantics.hpp"

namespace swarmcheck::supervisor {

std::optional<std::pair<State, State>> closed_loop_run(const Automaton& g, const Automaton& s,
                                                       const std::vector<Event>& word) {
  const auto x0 = initial_state(g);
  const auto y0 = initial_state(s);
  if (!x0 || !y0) return std::nullopt;
  std::pair<State, State> at{*x0, *y0};
  for (const auto& e : word) {
    const auto next = sync_successor(g, s, at.first, at.second, e);
    if (!next) return std::nullopt;
    at = *next;
  }
  return at;
}

bool is_uncontrollability_witness(const Automaton& g, const Automaton& s,
                                  const std::vector<Event>& word, const Event& e) {
  const auto at = closed_loop_run(g, s, word);
  if (!at) return false;
  for (const auto& d : uncontrollable_disabled(g, s, at->first, at->second))
    if (d == e) return true;
  return false;
}

}  // namespace swarmcheck::supervisor
