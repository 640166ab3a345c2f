#include "model/supervisor/operations.hpp"

#include <deque>

#include "spec/supervisor/semantics.hpp"
#include "spec/util/demand.hpp"
#include "spec/util/input_error.hpp"

namespace swarmcheck::model::supervisor {

// The spec's one-step rules (post, pre, sync_successor, ...) by their short names.
using namespace swarmcheck::supervisor;

namespace {

// Least fixpoint of X -> X u step(X) from `seed`: repeated whole-set passes.
template <class Step>
StateSet least_fixpoint(StateSet x, Step step) {
  for (;;) {
    StateSet next = x;
    for (const auto& q : step(x)) next.insert(q);
    if (next == x) return x;
    x = std::move(next);
  }
}

StateSet all_states(const Automaton& a) { return StateSet(a.states.begin(), a.states.end()); }

}  // namespace

StateSet accessible_states(const Automaton& a) {
  const auto q0 = initial_state(a);
  if (!q0) return {};
  return least_fixpoint({*q0}, [&](const StateSet& x) { return post(a, x); });
}

StateSet coaccessible_states(const Automaton& a) {
  return least_fixpoint(a.marked, [&](const StateSet& x) { return pre(a, x); });
}

Automaton accessible_part(const Automaton& a) { return restrict_to(a, accessible_states(a)); }

Automaton trim(const Automaton& a) {
  const StateSet ac = accessible_states(a);
  StateSet keep;
  for (const auto& q : coaccessible_states(a))
    if (ac.count(q)) keep.insert(q);
  return restrict_to(a, keep);
}

bool is_nonblocking(const Automaton& a) { return blocking_states(a).empty(); }

std::vector<State> blocking_states(const Automaton& a) {
  const StateSet ac = accessible_states(a);
  const StateSet coac = coaccessible_states(a);
  std::vector<State> out;
  for (const auto& q : a.states)
    if (ac.count(q) && !coac.count(q)) out.push_back(q);
  return out;
}

Product product2(const Automaton& g1, const std::string& name1, const Automaton& g2,
                 const std::string& name2) {
  Product p;
  p.automaton.events = alphabet_union(g1, name1, g2, name2);
  const auto q01 = initial_state(g1);
  const auto q02 = initial_state(g2);
  if (!q01 || !q02) return p;
  std::map<std::pair<State, State>, State> named;
  std::deque<std::pair<State, State>> queue;
  auto visit = [&](const std::pair<State, State>& xy) -> State {
    const auto hit = named.find(xy);
    if (hit != named.end()) return hit->second;
    const State z = pair_name(xy.first, xy.second);
    if (p.origin.count(z))
      throw InputError(name1 + " || " + name2,
                       "product state name '" + z + "' stands for two pairs of states; rename "
                       "states so that no name contains '.'");
    named.emplace(xy, z);
    p.origin.emplace(z, xy);
    p.automaton.states.push_back(z);
    if (g1.marked.count(xy.first) && g2.marked.count(xy.second)) p.automaton.marked.insert(z);
    queue.push_back(xy);
    return z;
  };
  visit({*q01, *q02});
  while (!queue.empty()) {
    const auto xy = queue.front();
    queue.pop_front();
    const State z = named.at(xy);
    for (const auto& [e, attr] : p.automaton.events) {
      const auto next = sync_successor(g1, g2, xy.first, xy.second, e);
      if (next) p.automaton.delta[z][e] = visit(*next);
    }
  }
  return p;
}

Automaton product(const std::vector<Automaton>& parts, const std::vector<std::string>& names) {
  SWARM_DEMAND(!parts.empty());
  SWARM_DEMAND(parts.size() == names.size());
  if (parts.size() == 1) {
    // The product of one automaton is its accessible part, numbered breadth-first like any
    // product: the product with a one-state automaton over no events, renamed back.
    Automaton unit;
    unit.states = {"u"};
    unit.marked = {"u"};
    const Product p = product2(parts.front(), names.front(), unit, "unit");
    Automaton out;
    out.events = p.automaton.events;
    auto back = [&](const State& z) { return p.origin.at(z).first; };
    for (const auto& z : p.automaton.states) out.states.push_back(back(z));
    for (const auto& z : p.automaton.marked) out.marked.insert(back(z));
    for (const auto& [z, row] : p.automaton.delta)
      for (const auto& [e, t] : row) out.delta[back(z)][e] = back(t);
    return out;
  }
  Automaton acc = parts.front();
  std::string acc_name = names.front();
  for (std::size_t i = 1; i < parts.size(); ++i) {
    acc = product2(acc, acc_name, parts[i], names[i]).automaton;
    acc_name += " || " + names[i];
  }
  return acc;
}

bool is_controllable(const Automaton& plant, const Automaton& spec) {
  const Product p = product2(plant, "plant", spec, "spec");
  for (const auto& [z, xy] : p.origin)
    if (!uncontrollable_disabled(plant, spec, xy.first, xy.second).empty()) return false;
  return true;
}

Automaton supcon(const Automaton& plant, const Automaton& spec) {
  const Product p = product2(plant, "plant", spec, "spec");
  StateSet x = all_states(p.automaton);
  for (;;) {
    StateSet good;
    for (const auto& z : x) {
      const auto& [gx, sy] = p.origin.at(z);
      if (supcon_good(plant, spec, p.automaton, z, gx, sy, x)) good.insert(z);
    }
    StateSet marked_good;
    for (const auto& z : p.automaton.marked)
      if (good.count(z)) marked_good.insert(z);
    const StateSet next = least_fixpoint(
        marked_good, [&](const StateSet& y) { return pre_within(p.automaton, y, good); });
    if (next == x) break;
    x = next;
  }
  return accessible_part(restrict_to(p.automaton, x));
}

Inclusion language_inclusion(const Automaton& a, const Automaton& b) {
  // Breadth-first over pairs (state of a, state of b or none): the first pair found that breaks
  // an inclusion carries a shortest witness.
  Inclusion out;
  const auto qa = initial_state(a);
  if (!qa) return out;
  using Node = std::pair<State, std::optional<State>>;
  std::map<Node, std::vector<Event>> word;
  std::deque<Node> queue;
  const Node start{*qa, initial_state(b)};
  word[start] = {};
  queue.push_back(start);
  while (!queue.empty()) {
    const Node n = queue.front();
    queue.pop_front();
    const auto& w = word.at(n);
    if (!n.second && out.closed) {
      out.closed = false;
      out.closed_witness = w;
    }
    if (a.marked.count(n.first) && (!n.second || !b.marked.count(*n.second)) && out.marked) {
      out.marked = false;
      out.marked_witness = w;
    }
    for (const auto& e : enabled(a, n.first)) {
      const Node next{*successor(a, n.first, e),
                      n.second ? successor(b, *n.second, e) : std::nullopt};
      if (word.count(next)) continue;
      auto longer = w;
      longer.push_back(e);
      word.emplace(next, std::move(longer));
      queue.push_back(next);
    }
  }
  return out;
}

}  // namespace swarmcheck::model::supervisor
