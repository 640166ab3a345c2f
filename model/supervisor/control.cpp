#include "model/supervisor/control.hpp"

#include <deque>

namespace swarmcheck::model::supervisor {

using namespace swarmcheck::supervisor;

ControlReport control_report(const Automaton& plant, const Automaton& sup) {
  ControlReport r;
  const Product p = product2(plant, "plant", sup, "supervisor");
  r.closed_loop_states = p.automaton.states.size();
  const auto q0 = initial_state(p.automaton);
  if (!q0) return r;
  const StateSet coac = coaccessible_states(p.automaton);
  std::map<State, std::vector<Event>> word{{*q0, {}}};
  std::deque<State> queue{*q0};
  bool found_blocking = false;
  while (!queue.empty()) {
    const State z = queue.front();
    queue.pop_front();
    const auto& w = word.at(z);
    const auto& [x, y] = p.origin.at(z);
    const auto disabled = uncontrollable_disabled(plant, sup, x, y);  // in name order
    if (r.controllable && !disabled.empty()) {
      r.controllable = false;
      r.witness = w;
      r.disabled_event = disabled.front();
    }
    if (!found_blocking && !coac.count(z)) {
      found_blocking = true;
      r.nonblocking = false;
      r.blocking_witness = w;
    }
    for (const auto& e : enabled(p.automaton, z)) {
      const State t = *successor(p.automaton, z, e);
      if (word.count(t)) continue;
      auto longer = w;
      longer.push_back(e);
      word.emplace(t, std::move(longer));
      queue.push_back(t);
    }
  }
  return r;
}

}  // namespace swarmcheck::model::supervisor
