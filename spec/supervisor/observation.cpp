#include "spec/supervisor/observation.hpp"

#include "spec/supervisor/control.hpp"
#include "spec/supervisor/semantics.hpp"
#include "spec/util/input_error.hpp"

namespace swarmcheck::supervisor {

std::vector<Event> unobservable_events(const std::map<Event, EventAttr>& events) {
  std::vector<Event> out;
  for (const auto& [e, attr] : events)
    if (!attr.observable) out.push_back(e);
  return out;
}

std::vector<Event> project(const Automaton& a, const std::vector<Event>& word) {
  std::vector<Event> out;
  for (const auto& e : word)
    if (a.events.at(e).observable) out.push_back(e);
  return out;
}

StateSet unobservable_post(const Automaton& a, const StateSet& x) {
  StateSet out;
  for (const auto& q : x)
    for (const auto& e : enabled(a, q))
      if (!a.events.at(e).observable) out.insert(*successor(a, q, e));
  return out;
}

StateSet post_event(const Automaton& a, const StateSet& x, const Event& e) {
  StateSet out;
  for (const auto& q : x)
    if (const auto t = successor(a, q, e)) out.insert(*t);
  return out;
}

std::string subset_name(const Automaton& a, const StateSet& x) {
  std::string out = "{";
  for (const auto& q : a.states)
    if (x.count(q)) out += (out.size() > 1 ? "," : "") + q;
  return out + "}";
}

void refuse_commas(const Automaton& a, const std::string& what) {
  for (const auto& q : a.states)
    if (q.find(',') != std::string::npos)
      throw InputError(what, "state '" + q + "' has a ',' in its name: an observer names its "
                             "states by the sets {q,r,...} they stand for; rename the state");
}

std::vector<Event> leaks(const Automaton& g, const Automaton& s, const State& x, const State& y) {
  std::vector<Event> out;
  for (const auto& e : enabled(g, x))
    if (s.events.count(e) && !successor(s, y, e)) out.push_back(e);
  return out;
}

bool is_unobservability_witness(const Automaton& g, const Automaton& s,
                                const ObservabilityReport& r) {
  if (r.observable) return false;
  const auto ev = g.events.find(r.event);
  if (ev == g.events.end() || !ev->second.controllable) return false;
  std::map<Event, EventAttr> all = g.events;
  for (const auto& [e, attr] : s.events) all.emplace(e, attr);
  auto projected = [&](const std::vector<Event>& w) {
    std::vector<Event> out;
    for (const auto& e : w)
      if (all.count(e) && all.at(e).observable) out.push_back(e);
    return out;
  };
  if (projected(r.word) != projected(r.twin)) return false;
  auto continued = r.word;
  continued.push_back(r.event);
  const auto at = closed_loop_run(g, s, r.twin);
  return closed_loop_run(g, s, continued).has_value() && at &&
         successor(g, at->first, r.event).has_value() &&
         s.events.count(r.event) && !successor(s, at->second, r.event);
}

}  // namespace swarmcheck::supervisor
