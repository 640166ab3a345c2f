#include "spec/supervisor/semantics.hpp"

#include "spec/util/input_error.hpp"

namespace swarmcheck::supervisor {

namespace {
std::string attr_words(const EventAttr& a) {
  return std::string(a.controllable ? "controllable" : "uncontrollable") + " and " +
         (a.observable ? "observable" : "unobservable");
}
}  // namespace

std::map<Event, EventAttr> alphabet_union(const Automaton& a, const std::string& a_name,
                                          const Automaton& b, const std::string& b_name) {
  std::map<Event, EventAttr> out = a.events;
  for (const auto& [e, attr] : b.events) {
    const auto [it, inserted] = out.emplace(e, attr);
    if (!inserted && !(it->second == attr))
      throw InputError(b_name, "event '" + e + "' is " + attr_words(attr) + " here but " +
                                   attr_words(it->second) + " in " + a_name);
  }
  return out;
}

StateSet post(const Automaton& a, const StateSet& x) {
  StateSet out;
  for (const auto& q : x) {
    const auto row = a.delta.find(q);
    if (row == a.delta.end()) continue;
    for (const auto& [e, target] : row->second) out.insert(target);
  }
  return out;
}

StateSet pre(const Automaton& a, const StateSet& x) {
  StateSet out;
  for (const auto& [q, row] : a.delta)
    for (const auto& [e, target] : row)
      if (x.count(target)) out.insert(q);
  return out;
}

StateSet pre_within(const Automaton& a, const StateSet& x, const StateSet& within) {
  StateSet out;
  for (const auto& q : pre(a, x))
    if (within.count(q)) out.insert(q);
  return out;
}

Automaton restrict_to(const Automaton& a, const StateSet& keep) {
  Automaton out;
  out.events = a.events;
  if (a.states.empty() || !keep.count(a.states.front())) return out;
  for (const auto& q : a.states) {
    if (!keep.count(q)) continue;
    out.states.push_back(q);
    if (a.marked.count(q)) out.marked.insert(q);
    const auto row = a.delta.find(q);
    if (row == a.delta.end()) continue;
    for (const auto& [e, target] : row->second)
      if (keep.count(target)) out.delta[q][e] = target;
  }
  return out;
}

State pair_name(const State& x1, const State& x2) { return x1 + "." + x2; }

std::optional<std::pair<State, State>> sync_successor(const Automaton& g1, const Automaton& g2,
                                                      const State& x1, const State& x2,
                                                      const Event& e) {
  const bool in1 = g1.events.count(e) != 0;
  const bool in2 = g2.events.count(e) != 0;
  if (!in1 && !in2) return std::nullopt;
  std::optional<State> y1 = in1 ? successor(g1, x1, e) : std::optional<State>(x1);
  std::optional<State> y2 = in2 ? successor(g2, x2, e) : std::optional<State>(x2);
  if (!y1 || !y2) return std::nullopt;
  return std::make_pair(*y1, *y2);
}

std::vector<Event> uncontrollable_disabled(const Automaton& g, const Automaton& s, const State& x,
                                           const State& y) {
  std::vector<Event> out;
  for (const auto& e : enabled(g, x)) {
    if (g.events.at(e).controllable) continue;
    if (s.events.count(e) && !successor(s, y, e)) out.push_back(e);
  }
  return out;
}

bool supcon_good(const Automaton& g, const Automaton& s, const Automaton& p, const State& z,
                 const State& x, const State& y, const StateSet& candidates) {
  if (!uncontrollable_disabled(g, s, x, y).empty()) return false;
  for (const auto& e : enabled(g, x)) {
    if (g.events.at(e).controllable) continue;
    const auto next = successor(p, z, e);
    if (!next || !candidates.count(*next)) return false;
  }
  return true;
}

std::optional<State> run(const Automaton& a, const std::vector<Event>& word) {
  std::optional<State> q = initial_state(a);
  for (const auto& e : word) {
    if (!q) return std::nullopt;
    q = successor(a, *q, e);
  }
  return q;
}

bool in_closed_language(const Automaton& a, const std::vector<Event>& word) {
  return run(a, word).has_value();
}

bool in_marked_language(const Automaton& a, const std::vector<Event>& word) {
  const auto q = run(a, word);
  return q && a.marked.count(*q) != 0;
}

}  // namespace swarmcheck::supervisor
