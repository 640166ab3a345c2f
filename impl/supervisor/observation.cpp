// Partial observation on the compact form (spec/supervisor/observation.hpp): the observer by
// subset construction (sorted id vectors in a hash map), the twin search of observability with
// parent links, and the controllable normal supervisor as a fixpoint over observer classes.
// Every breadth-first order is the model's (model/supervisor/observation.hpp), so results agree
// state for state.
#include <algorithm>
#include <deque>
#include <unordered_map>

#include "impl/supervisor/operations.hpp"
#include "impl/supervisor/reach.hpp"
#include "spec/util/budget.hpp"
#include "spec/util/input_error.hpp"

namespace swarmcheck::impl::supervisor {

namespace {

struct IdsHash {
  std::size_t operator()(const std::vector<StateId>& v) const {
    std::uint64_t h = 1469598103934665603ull;
    for (const StateId s : v) h = (h ^ s) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

// The observer's classes (sorted member ids) in breadth-first order, and next[k][e] (e an event
// id of f; kNoState when post_e is empty or e is unobservable).
struct ObserverClasses {
  std::vector<std::vector<StateId>> sets;
  std::vector<std::vector<StateId>> next;
};

// A construction's budget, the model of its command's peak, and what its messages name.
struct Guard {
  WorkBudget& budget;
  PeakModel peak;
  std::string where;
};

// The legacy models of the byte-limit entry points (the library's named results): per class the
// index's node and bucket, three vectors (key, list, row of successors) with their heap blocks,
// so 176 bytes + 4 per event; per member 8 (key and list) and 4 for what is built from the
// classes afterwards (an observer's state names, H's pairs).
PeakModel legacy_observer_peak(const Fsm& f) { return PeakModel{0, 176.0 + 4.0 * static_cast<double>(f.event_count()), 12.0}; }

// The subset construction can be exponential in the states, so it is what a budget guards: the
// model of (classes, members of all classes, the members of the classes not yet explored
// extrapolated from those explored).
ObserverClasses observer_classes(const Fsm& f, const Guard& guard) {
  ObserverClasses c;
  if (f.state_count() == 0) return c;
  std::vector<std::uint32_t> stamp(f.state_count(), 0);
  std::uint32_t round = 0;
  // UR of `x` (distinct ids), returned sorted.
  auto reach = [&](std::vector<StateId> x) {
    ++round;
    for (const StateId s : x) stamp[s] = round;
    for (std::size_t i = 0; i < x.size(); ++i)
      for (auto j = f.first_edge[x[i]]; j < f.first_edge[x[i] + 1]; ++j) {
        const StateId t = f.edge_target[j];
        if (!f.observable[f.edge_event[j]] && stamp[t] != round) {
          stamp[t] = round;
          x.push_back(t);
        }
      }
    std::sort(x.begin(), x.end());
    return x;
  };
  std::unordered_map<std::vector<StateId>, StateId, IdsHash> index;
  auto visit = [&](std::vector<StateId> x) {
    const auto [it, fresh] = index.emplace(std::move(x), static_cast<StateId>(c.sets.size()));
    if (fresh) {
      c.sets.push_back(it->first);
      c.next.emplace_back(f.event_count(), kNoState);
    }
    return it->second;
  };
  visit(reach({0}));
  std::vector<StateId> post;
  double members = 0;
  for (std::size_t k = 0; k < c.sets.size(); ++k) {
    members += static_cast<double>(c.sets[k].size());
    if (k % 256 == 0) {
      const double classes = static_cast<double>(c.sets.size());
      guard.budget.check(guard.where, guard.peak.at(classes, members * classes / static_cast<double>(k + 1)), [&] {
        return "the observer stopped after " + std::to_string(k) + " classes (" + std::to_string(c.sets.size()) + " found)";
      });
    }
    for (EventId e = 0; e < f.event_count(); ++e) {
      if (!f.observable[e]) continue;
      ++round;
      post.clear();
      for (const StateId s : c.sets[k]) {
        const StateId t = f.successor(s, e);
        if (t != kNoState && stamp[t] != round) {
          stamp[t] = round;
          post.push_back(t);
        }
      }
      if (post.empty()) continue;
      const StateId t = visit(reach(post));
      c.next[k][e] = t;
    }
  }
  guard.budget.note(guard.peak.at(static_cast<double>(c.sets.size()), members));
  return c;
}

void refuse_commas(const Fsm& f, const std::string& what, const AppendName& name) {
  std::string s;
  for (StateId q = 0; q < f.state_count(); ++q) {
    s.clear();
    name(q, s);
    if (s.find(',') != std::string::npos)
      throw InputError(what, "state '" + s + "' has a ',' in its name: an observer names its "
                             "states by the sets {q,r,...} they stand for; rename the state");
  }
}

}  // namespace

Fsm observer(const Fsm& f, std::uint64_t max_bytes, const std::string& where) {
  WorkBudget budget(max_bytes);
  return observer(f, budget, legacy_observer_peak(f), where);
}

Fsm observer(const Fsm& f, WorkBudget& budget, const PeakModel& peak, const std::string& where) {
  refuse_commas(f, "observer", name_speller(f));
  const ObserverClasses c = observer_classes(f, Guard{budget, peak, where});
  Fsm out;
  std::vector<EventId> renumber(f.event_count(), kNoEvent);
  for (EventId e = 0; e < f.event_count(); ++e)
    if (f.observable[e]) {
      renumber[e] = out.event_count();
      out.event_names.push_back(f.event_names[e]);
      out.controllable.push_back(f.controllable[e]);
      out.observable.push_back(1);
    }
  std::vector<std::vector<std::pair<EventId, StateId>>> edges(c.sets.size());
  for (std::size_t k = 0; k < c.sets.size(); ++k) {
    std::string name = "{";
    std::uint8_t marked = 0;
    for (const StateId s : c.sets[k]) {
      if (name.size() > 1) name += ',';
      name += f.state_names[s];
      marked |= f.marked[s];
    }
    out.state_names.push_back(name + "}");
    out.marked.push_back(marked);
    for (EventId e = 0; e < f.event_count(); ++e)
      if (c.next[k][e] != kNoState) edges[k].emplace_back(renumber[e], c.next[k][e]);
  }
  set_edges(out, edges);
  return out;
}

swarmcheck::supervisor::ObservabilityReport observability(const Fsm& plant, const Fsm& spec) {
  WorkBudget none;
  return observability(plant, spec, none, PeakModel{}, PeakModel{});
}

swarmcheck::supervisor::ObservabilityReport observability(const Fsm& plant, const Fsm& spec, WorkBudget& budget,
                                                          const PeakModel& product_peak, const PeakModel& pairs_peak) {
  swarmcheck::supervisor::ObservabilityReport r;
  const Product loop = product_with_tuples({&plant, &spec}, {"plant", "spec"}, budget, product_peak, "plant || spec");
  const Fsm& a = loop.fsm;
  if (a.state_count() == 0) return r;
  std::vector<EventId> in_a(plant.event_count());
  for (EventId e = 0; e < plant.event_count(); ++e) in_a[e] = a.event_id(plant.event_names[e]);
  struct Node {
    StateId z1, z2;
    std::uint32_t parent;
    EventId event;       // the move from the parent
    std::uint8_t sides;  // 1: first word, 2: second, 3: both
  };
  std::vector<Node> nodes;
  std::unordered_map<std::uint64_t, std::uint32_t> seen;
  auto visit = [&](StateId z1, StateId z2, std::uint32_t parent, EventId e, std::uint8_t sides) {
    const std::uint64_t key = (std::uint64_t{z1} << 32) | z2;
    if (seen.emplace(key, static_cast<std::uint32_t>(nodes.size())).second)
      nodes.push_back({z1, z2, parent, e, sides});
  };
  visit(0, 0, UINT32_MAX, 0, 0);
  // The pairs of closed-loop states are quadratic in them (1 000 states of a chain: 30 s, 2 GB);
  // the closed loop itself is held meanwhile.
  const double held = product_peak.at(static_cast<double>(a.state_count()), static_cast<double>(a.edge_count()));
  for (std::uint32_t i = 0; i < nodes.size(); ++i) {
    if (i % 4096 == 0)
      budget.check("plant || spec", held + pairs_peak.at(static_cast<double>(nodes.size()), 0), [&] {
        return "the observability check stopped after comparing " + std::to_string(i) + " pairs of words' states (" +
               std::to_string(nodes.size()) + " found, of up to " + std::to_string(std::uint64_t{a.state_count()} * a.state_count()) +
               "), with no verdict";
      });
    const Node n = nodes[i];
    const StateId x2 = loop.names.tuple(n.z2)[0];
    for (auto j = plant.first_edge[x2]; j < plant.first_edge[x2 + 1]; ++j) {
      const EventId e = plant.edge_event[j];
      if (!plant.controllable[e]) continue;
      if (a.successor(n.z1, in_a[e]) != kNoState && a.successor(n.z2, in_a[e]) == kNoState) {
        r.observable = false;
        r.event = plant.event_names[e];
        for (std::uint32_t k = i; nodes[k].parent != UINT32_MAX; k = nodes[k].parent) {
          if (nodes[k].sides & 1) r.word.push_back(a.event_names[nodes[k].event]);
          if (nodes[k].sides & 2) r.twin.push_back(a.event_names[nodes[k].event]);
        }
        std::reverse(r.word.begin(), r.word.end());
        std::reverse(r.twin.begin(), r.twin.end());
        budget.note(held + pairs_peak.at(static_cast<double>(nodes.size()), 0));
        return r;
      }
    }
    for (EventId e = 0; e < a.event_count(); ++e) {
      const StateId t1 = a.successor(n.z1, e), t2 = a.successor(n.z2, e);
      if (a.observable[e]) {
        if (t1 != kNoState && t2 != kNoState) visit(t1, t2, i, e, 3);
        continue;
      }
      if (t1 != kNoState) visit(t1, n.z2, i, e, 1);
      if (t2 != kNoState) visit(n.z1, t2, i, e, 2);
    }
  }
  budget.note(held + pairs_peak.at(static_cast<double>(nodes.size()), 0));
  return r;
}

Fsm supcon_normal(const Fsm& plant, const Fsm& spec, std::uint64_t max_bytes) {
  WorkBudget budget(max_bytes);
  NormalPeaks legacy;
  legacy.product = PeakModel{0, 208.0, 16.0};
  legacy.pairs = PeakModel{0, 96.0, 8.0};
  const std::size_t events = plant.event_count() + spec.event_count();   // at least the closed loop's
  legacy.observer = PeakModel{0, 176.0 + 4.0 * static_cast<double>(events), 12.0};
  return supcon_normal(plant, spec, budget, legacy);
}

Fsm supcon_normal(const Fsm& plant, const Fsm& spec, WorkBudget& budget, const NormalPeaks& peaks) {
  const Product loop = product_with_tuples({&plant, &spec}, {"plant", "spec"}, budget, peaks.product, "plant || spec");
  const Fsm& a = loop.fsm;
  // Each stage's estimate adds its own model to what the stages before it came to.
  double held = peaks.product.at(static_cast<double>(a.state_count()), static_cast<double>(a.edge_count()));
  PeakModel observer_peak = peaks.observer;
  observer_peak.fixed += held;
  const ObserverClasses c = observer_classes(a, Guard{budget, observer_peak, "plant || spec"});
  {
    double members = 0;
    for (const auto& set : c.sets) members += static_cast<double>(set.size());
    held = observer_peak.at(static_cast<double>(c.sets.size()), members);
  }
  // H: pairs (z, k), breadth first from (0, 0).
  Fsm h;
  h.event_names = a.event_names;
  h.controllable = a.controllable;
  h.observable = a.observable;
  std::vector<std::pair<StateId, StateId>> origin;
  std::vector<std::vector<std::pair<EventId, StateId>>> edges;
  if (a.state_count() > 0) {
    std::unordered_map<std::uint64_t, StateId> seen;
    auto visit = [&](StateId z, StateId k) {
      const auto [it, fresh] =
          seen.emplace((std::uint64_t{z} << 32) | k, static_cast<StateId>(origin.size()));
      if (fresh) {
        origin.emplace_back(z, k);
        h.marked.push_back(a.marked[z]);
        edges.emplace_back();
      }
      return it->second;
    };
    visit(0, 0);
    double edge_count = 0;
    for (StateId s = 0; s < origin.size(); ++s) {
      if (s % 4096 == 0)
        budget.check("plant || spec", held + peaks.pairs.at(static_cast<double>(origin.size()), edge_count), [&] {
          return "normal synthesis stopped after " + std::to_string(s) + " (state, observer class) pairs (" +
                 std::to_string(origin.size()) + " found)";
        });
      const auto [z, k] = origin[s];
      for (auto i = a.first_edge[z]; i < a.first_edge[z + 1]; ++i) {
        const EventId e = a.edge_event[i];
        const StateId t = visit(a.edge_target[i], a.observable[e] ? c.next[k][e] : k);
        edges[s].emplace_back(e, t);
      }
      edge_count += static_cast<double>(a.first_edge[z + 1] - a.first_edge[z]);
    }
    held += peaks.pairs.at(static_cast<double>(origin.size()), edge_count);
    budget.note(held);
  }
  set_edges(h, edges);
  const StateId n = h.state_count();
  // Leaks: the plant enables e at x and the closed loop does not (so the spec disables it).
  std::vector<EventId> in_a(plant.event_count());
  std::vector<std::uint8_t> unc_plant(a.event_count(), 0);  // the plant's uncontrollable events
  for (EventId e = 0; e < plant.event_count(); ++e) {
    in_a[e] = a.event_id(plant.event_names[e]);
    if (!plant.controllable[e]) unc_plant[in_a[e]] = 1;
  }
  std::vector<std::uint8_t> kept(c.sets.size(), 1);
  for (std::size_t k = 0; k < c.sets.size(); ++k)
    for (const StateId z : c.sets[k]) {
      const StateId x = loop.names.tuple(z)[0];
      for (auto i = plant.first_edge[x]; i < plant.first_edge[x + 1]; ++i) {
        const EventId e = in_a[plant.edge_event[i]];
        if (a.successor(z, e) != kNoState) continue;
        if (!a.observable[e]) kept[k] = 0;
        else if (c.next[k][e] != kNoState) kept[c.next[k][e]] = 0;
      }
    }
  const std::vector<EventId> disabled = disabled_uncontrollable(plant, loop);
  const ReverseEdges back = reverse_edges(h);
  std::vector<std::uint8_t> inside(n), seeds(n);
  // As many passes as observer classes may be needed, each linear in H: the clock is checked.
  for (int passes = 0;; ++passes) {
    budget.check("plant || spec", held, [&] {
      return "normal synthesis stopped after " + std::to_string(passes) + " passes of its fixpoint over " + std::to_string(n) +
             " (state, observer class) pairs";
    });
    std::vector<std::uint8_t> good = kept;
    for (StateId s = 0; s < n; ++s) {
      const auto [z, k] = origin[s];
      if (!kept[k]) continue;
      if (disabled[z] != kNoEvent) good[k] = 0;
      for (auto i = h.first_edge[s]; i < h.first_edge[s + 1]; ++i)
        if (unc_plant[h.edge_event[i]] && !kept[origin[h.edge_target[i]].second]) good[k] = 0;
    }
    for (StateId s = 0; s < n; ++s) {
      inside[s] = good[origin[s].second];
      seeds[s] = inside[s] && h.marked[s];
    }
    const auto reach = coreachable(back, seeds, &inside);
    for (StateId s = 0; s < n; ++s)
      if (inside[s] && !reach[s]) good[origin[s].second] = 0;
    if (good == kept) break;
    kept = std::move(good);
  }
  std::vector<std::uint8_t> keep(n);
  for (StateId s = 0; s < n; ++s) keep[s] = kept[origin[s].second];
  std::string name;
  for (StateId s = 0; s < n; ++s) {
    name.clear();
    loop.names.append(origin[s].first, name);
    h.state_names.push_back(name + ".o" + std::to_string(origin[s].second));
  }
  const Fsm candidates = restrict_states(h, keep);
  return restrict_states(candidates, accessible_mask(candidates));
}

}  // namespace swarmcheck::impl::supervisor
