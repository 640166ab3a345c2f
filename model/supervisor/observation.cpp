#include "model/supervisor/observation.hpp"

#include <deque>

namespace swarmcheck::model::supervisor {

using namespace swarmcheck::supervisor;

namespace {

StateSet unobservable_reach(const Automaton& a, StateSet x) {
  for (;;) {
    StateSet next = x;
    for (const auto& q : unobservable_post(a, x)) next.insert(q);
    if (next == x) return x;
    x = std::move(next);
  }
}

// The observer's classes in breadth-first order and its transitions between their indices.
struct Classes {
  std::vector<StateSet> sets;
  std::vector<std::map<Event, std::size_t>> next;
};

Classes observer_classes(const Automaton& a) {
  Classes c;
  const auto q0 = initial_state(a);
  if (!q0) return c;
  std::map<StateSet, std::size_t> index;
  auto visit = [&](const StateSet& x) {
    const auto [it, fresh] = index.emplace(x, c.sets.size());
    if (fresh) {
      c.sets.push_back(x);
      c.next.emplace_back();
    }
    return it->second;
  };
  visit(unobservable_reach(a, {*q0}));
  for (std::size_t k = 0; k < c.sets.size(); ++k)
    for (const auto& [e, attr] : a.events) {
      if (!attr.observable) continue;
      const StateSet y = post_event(a, c.sets[k], e);
      if (y.empty()) continue;
      const std::size_t t = visit(unobservable_reach(a, y));
      c.next[k][e] = t;
    }
  return c;
}

}  // namespace

Automaton observer(const Automaton& a) {
  refuse_commas(a, "observer");
  Automaton out;
  for (const auto& [e, attr] : a.events)
    if (attr.observable) out.events[e] = attr;
  const Classes c = observer_classes(a);
  for (std::size_t k = 0; k < c.sets.size(); ++k) {
    const State name = subset_name(a, c.sets[k]);
    out.states.push_back(name);
    for (const auto& q : c.sets[k])
      if (a.marked.count(q)) out.marked.insert(name);
    for (const auto& [e, t] : c.next[k]) out.delta[name][e] = subset_name(a, c.sets[t]);
  }
  return out;
}

ObservabilityReport observability(const Automaton& plant, const Automaton& spec) {
  ObservabilityReport r;
  const Product p = product2(plant, "plant", spec, "spec");
  const Automaton& a = p.automaton;
  const auto z0 = initial_state(a);
  if (!z0) return r;
  using Node = std::pair<State, State>;
  using Twin = std::pair<std::vector<Event>, std::vector<Event>>;
  std::map<Node, Twin> words;
  std::deque<Node> queue;
  auto visit = [&](const Node& n, Twin w) {
    if (words.emplace(n, std::move(w)).second) queue.push_back(n);
  };
  visit({*z0, *z0}, {});
  while (!queue.empty()) {
    const Node n = queue.front();
    queue.pop_front();
    const Twin w = words.at(n);
    const State& x2 = p.origin.at(n.second).first;
    for (const auto& e : enabled(plant, x2)) {
      if (!plant.events.at(e).controllable) continue;
      if (successor(a, n.first, e) && !successor(a, n.second, e)) {
        r = {false, w.first, w.second, e};
        return r;
      }
    }
    for (const auto& [e, attr] : a.events) {
      const auto t1 = successor(a, n.first, e);
      const auto t2 = successor(a, n.second, e);
      auto add = [&](std::vector<Event> v) {
        v.push_back(e);
        return v;
      };
      if (attr.observable) {
        if (t1 && t2) visit({*t1, *t2}, {add(w.first), add(w.second)});
        continue;
      }
      if (t1) visit({*t1, n.second}, {add(w.first), w.second});
      if (t2) visit({n.first, *t2}, {w.first, add(w.second)});
    }
  }
  return r;
}

Automaton supcon_normal(const Automaton& plant, const Automaton& spec) {
  const Product p = product2(plant, "plant", spec, "spec");
  const Automaton& a = p.automaton;
  const Classes c = observer_classes(a);
  // H, breadth first from (z0, 0).
  Automaton h;
  h.events = a.events;
  std::map<State, std::pair<State, std::size_t>> origin;
  if (!c.sets.empty()) {
    std::map<std::pair<State, std::size_t>, State> named;
    std::deque<std::pair<State, std::size_t>> queue;
    auto visit = [&](const std::pair<State, std::size_t>& zk) {
      const auto hit = named.find(zk);
      if (hit != named.end()) return hit->second;
      const State name = pair_name(zk.first, "o" + std::to_string(zk.second));
      named.emplace(zk, name);
      origin.emplace(name, zk);
      h.states.push_back(name);
      if (a.marked.count(zk.first)) h.marked.insert(name);
      queue.push_back(zk);
      return name;
    };
    visit({a.states.front(), 0});
    while (!queue.empty()) {
      const auto zk = queue.front();
      queue.pop_front();
      const State from = named.at(zk);
      for (const auto& [e, attr] : a.events) {
        const auto t = successor(a, zk.first, e);
        if (!t) continue;
        const std::size_t k = attr.observable ? c.next[zk.second].at(e) : zk.second;
        h.delta[from][e] = visit({*t, k});
      }
    }
  }
  // The spoiled classes.
  std::set<std::size_t> classes;
  for (std::size_t k = 0; k < c.sets.size(); ++k) classes.insert(k);
  for (std::size_t k = 0; k < c.sets.size(); ++k)
    for (const auto& z : c.sets[k]) {
      const auto& [x, y] = p.origin.at(z);
      for (const auto& e : leaks(plant, spec, x, y)) {
        if (!a.events.at(e).observable) {
          classes.erase(k);
        } else {
          const auto t = c.next[k].find(e);
          if (t != c.next[k].end()) classes.erase(t->second);
        }
      }
    }
  auto class_of = [&](const State& hz) { return origin.at(hz).second; };
  for (;;) {
    std::set<std::size_t> good = classes;
    for (const auto& hz : h.states) {
      const auto& [z, k] = origin.at(hz);
      if (!classes.count(k)) continue;
      const auto& [x, y] = p.origin.at(z);
      if (!uncontrollable_disabled(plant, spec, x, y).empty()) good.erase(k);
      for (const auto& e : enabled(plant, x)) {
        if (plant.events.at(e).controllable) continue;
        const auto t = successor(h, hz, e);
        if (t && !classes.count(class_of(*t))) good.erase(k);
      }
    }
    StateSet inside, reach;
    for (const auto& hz : h.states)
      if (good.count(class_of(hz))) inside.insert(hz);
    for (const auto& hz : h.marked)
      if (inside.count(hz)) reach.insert(hz);
    for (;;) {
      StateSet next = reach;
      for (const auto& q : pre_within(h, reach, inside)) next.insert(q);
      if (next == reach) break;
      reach = std::move(next);
    }
    std::set<std::size_t> next = good;
    for (const auto& hz : inside)
      if (!reach.count(hz)) next.erase(class_of(hz));
    if (next == classes) break;
    classes = std::move(next);
  }
  StateSet keep;
  for (const auto& hz : h.states)
    if (classes.count(class_of(hz))) keep.insert(hz);
  return accessible_part(restrict_to(h, keep));
}

}  // namespace swarmcheck::model::supervisor
