#pragma once
// RapidCheck generators of random deterministic automata (header-only: only test code links
// RapidCheck). Automata are built from flat lists of (from, event, to) triples and marking
// flags, so shrinking removes transitions and states one at a time down to a minimal pair.
// Automata that are composed share one alphabet, so attributes never conflict.
#include <rapidcheck.h>

#include <algorithm>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "spec/supervisor/automaton.hpp"

namespace swarmcheck::conformance::supervisor {

using swarmcheck::supervisor::Automaton;
using swarmcheck::supervisor::EventAttr;
using Alphabet = std::map<std::string, EventAttr>;

// prefix + i, appended rather than concatenated: GCC 12 warns falsely (-Wrestrict) on "q" + s.
inline std::string numbered(const char* prefix, std::size_t i) {
  std::string s = prefix;
  s += std::to_string(i);
  return s;
}

// An integer uniform in [lo, hi), whatever the current size: sizes scale the state count
// explicitly (below), and RapidCheck's own scaling of inRange would shrink everything twice.
inline rc::Gen<int> uniform(int lo, int hi) { return rc::gen::resize(100, rc::gen::inRange(lo, hi)); }

inline rc::Gen<bool> chance(int pct) {
  return rc::gen::map(uniform(0, 100), [pct](int k) { return k < pct; });
}

// 1 to 6 events "e0".."e5" controllable with probability 0.65, observable 0.5.
inline rc::Gen<Alphabet> gen_alphabet() {
  return rc::gen::mapcat(rc::gen::resize(100, rc::gen::inRange(1, 7)), [](int n) {
    return rc::gen::map(
        rc::gen::container<std::vector<std::pair<bool, bool>>>(
            static_cast<std::size_t>(n),
            rc::gen::pair(chance(65), rc::gen::arbitrary<bool>())),
        [](const std::vector<std::pair<bool, bool>>& attrs) {
          Alphabet a;
          for (std::size_t i = 0; i < attrs.size(); ++i)
            a[numbered("e", i)] = EventAttr{attrs[i].first, attrs[i].second};
          return a;
        });
  });
}

// The raw material of an automaton: state count, transitions, marking, which events it has.
struct RawAutomaton {
  int states = 1;
  std::vector<std::tuple<int, int, int>> transitions;  // (from, event index, to)
  std::vector<bool> marked;                             // by state index
  std::vector<bool> has_event;                          // by alphabet index
};

// First transition per (state, event) wins: the result is deterministic by construction.
inline Automaton build(const Alphabet& alphabet, const RawAutomaton& raw) {
  std::vector<std::string> events;
  for (const auto& [e, attr] : alphabet) events.push_back(e);
  Automaton a;
  for (int i = 0; i < raw.states; ++i) a.states.push_back(numbered("q", static_cast<std::size_t>(i)));
  for (std::size_t i = 0; i < events.size(); ++i)
    if (i >= raw.has_event.size() || raw.has_event[i]) a.events[events[i]] = alphabet.at(events[i]);
  for (std::size_t i = 0; i < raw.marked.size() && i < a.states.size(); ++i)
    if (raw.marked[i]) a.marked.insert(a.states[i]);
  for (const auto& [from, e, to] : raw.transitions) {
    if (from >= raw.states || to >= raw.states || e >= static_cast<int>(events.size())) continue;
    if (!a.events.count(events[e])) continue;
    a.delta[a.states[from]].emplace(events[e], a.states[to]);
  }
  return a;
}

// The shape of generated automata: at most states_max states (reached at RapidCheck size 100),
// about density_pct transitions per 100 (state, event) pairs, marked_pct of states marked.
struct Shape {
  int states_max = 40;
  int density_pct = 60;
  int marked_pct = 25;
};

// An automaton over (a subset of) `alphabet`, its state count growing with the size.
inline rc::Gen<Automaton> gen_automaton(const Alphabet& alphabet, Shape shape) {
  const int events = static_cast<int>(alphabet.size());
  return rc::gen::withSize([=](int size) {
    const int cap = std::max(1, std::min(shape.states_max, 1 + size * shape.states_max / 100));
    return rc::gen::mapcat(uniform(1, cap + 1), [=](int n) {
      const auto triple = rc::gen::tuple(uniform(0, n), uniform(0, events), uniform(0, n));
      const int expected = std::max(1, n * events * shape.density_pct / 100);
      return rc::gen::map(
          rc::gen::tuple(
              rc::gen::mapcat(uniform(expected / 2, expected + 1),
                              [=](int m) {
                                return rc::gen::container<std::vector<std::tuple<int, int, int>>>(
                                    static_cast<std::size_t>(m), triple);
                              }),
              rc::gen::container<std::vector<bool>>(static_cast<std::size_t>(n),
                                                    chance(shape.marked_pct)),
              rc::gen::container<std::vector<bool>>(static_cast<std::size_t>(events), chance(85))),
          [=](const std::tuple<std::vector<std::tuple<int, int, int>>, std::vector<bool>,
                               std::vector<bool>>& parts) {
            RawAutomaton raw;
            raw.states = n;
            raw.transitions = std::get<0>(parts);
            raw.marked = std::get<1>(parts);
            raw.has_event = std::get<2>(parts);
            return build(alphabet, raw);
          });
    });
  });
}

}  // namespace swarmcheck::conformance::supervisor
