#include "spec/supervisor/automaton.hpp"

namespace swarmcheck::supervisor {

std::optional<State> initial_state(const Automaton& a) {
  if (a.states.empty()) return std::nullopt;
  return a.states.front();
}

std::optional<State> successor(const Automaton& a, const State& q, const Event& e) {
  const auto row = a.delta.find(q);
  if (row == a.delta.end()) return std::nullopt;
  const auto hit = row->second.find(e);
  if (hit == row->second.end()) return std::nullopt;
  return hit->second;
}

std::vector<Event> enabled(const Automaton& a, const State& q) {
  std::vector<Event> out;
  const auto row = a.delta.find(q);
  if (row == a.delta.end()) return out;
  for (const auto& [e, target] : row->second) out.push_back(e);
  return out;
}

std::size_t transition_count(const Automaton& a) {
  std::size_t n = 0;
  for (const auto& [q, row] : a.delta) n += row.size();
  return n;
}

std::string well_formedness_error(const Automaton& a) {
  const std::set<State> known(a.states.begin(), a.states.end());
  if (known.size() != a.states.size()) return "a state name occurs twice";
  for (const auto& q : a.marked)
    if (!known.count(q)) return "marked state '" + q + "' is not a state";
  for (const auto& [q, row] : a.delta) {
    if (!known.count(q)) return "transitions from '" + q + "', which is not a state";
    for (const auto& [e, target] : row) {
      if (!a.events.count(e)) return "event '" + e + "' is not in the alphabet";
      if (!known.count(target)) return "target '" + target + "' is not a state";
    }
  }
  return "";
}

}  // namespace swarmcheck::supervisor
