#include "impl/supervisor/fsm.hpp"

#include <algorithm>
#include <unordered_map>

#include "spec/util/demand.hpp"

namespace swarmcheck::impl::supervisor {

StateId Fsm::successor(StateId s, EventId e) const {
  SWARM_ASSERT(s < state_count());
  const auto begin = edge_event.begin() + first_edge[s];
  const auto end = edge_event.begin() + first_edge[s + 1];
  const auto hit = std::lower_bound(begin, end, e);
  if (hit == end || *hit != e) return kNoState;
  return edge_target[static_cast<std::size_t>(hit - edge_event.begin())];
}

EventId Fsm::event_id(const std::string& name) const {
  const auto hit = std::lower_bound(event_names.begin(), event_names.end(), name);
  if (hit == event_names.end() || *hit != name) return UINT32_MAX;
  return static_cast<EventId>(hit - event_names.begin());
}

void set_edges(Fsm& f, const std::vector<std::vector<std::pair<EventId, StateId>>>& edges) {
  SWARM_DEMAND(edges.size() == f.marked.size());
  f.first_edge.assign(edges.size() + 1, 0);
  f.edge_event.clear();
  f.edge_target.clear();
  for (std::size_t s = 0; s < edges.size(); ++s) {
    for (const auto& [e, t] : edges[s]) {
      f.edge_event.push_back(e);
      f.edge_target.push_back(t);
    }
    f.first_edge[s + 1] = static_cast<std::uint32_t>(f.edge_event.size());
  }
}

Fsm compile(const swarmcheck::supervisor::Automaton& a) {
  Fsm f;
  for (const auto& [e, attr] : a.events) {  // std::map: already in name order
    f.event_names.push_back(e);
    f.controllable.push_back(attr.controllable ? 1 : 0);
    f.observable.push_back(attr.observable ? 1 : 0);
  }
  std::unordered_map<std::string, StateId> id;
  for (const auto& q : a.states) {
    id.emplace(q, static_cast<StateId>(f.state_names.size()));
    f.state_names.push_back(q);
    f.marked.push_back(a.marked.count(q) ? 1 : 0);
  }
  std::vector<std::vector<std::pair<EventId, StateId>>> edges(a.states.size());
  for (const auto& [q, row] : a.delta)
    for (const auto& [e, target] : row)  // row in event-name order, hence ascending ids
      edges[id.at(q)].emplace_back(f.event_id(e), id.at(target));
  set_edges(f, edges);
  return f;
}

void TupleNames::append(StateId s, std::string& out) const {
  const StateId* t = tuple(s);
  for (std::size_t p = 0; p < parts.size(); ++p) {
    if (p > 0) out += '.';
    out += parts[p]->state_names[t[p]];
  }
}

std::string TupleNames::name(StateId s) const {
  std::string out;
  append(s, out);
  return out;
}

AppendName name_speller(const Fsm& f, const TupleNames* tuples) {
  if (tuples) return [tuples](StateId s, std::string& out) { tuples->append(s, out); };
  SWARM_DEMAND(f.named());
  return [&f](StateId s, std::string& out) { out += f.state_names[s]; };
}

void store_names(Fsm& f, const TupleNames& tuples) {
  SWARM_DEMAND(tuples.tuples.size() == std::size_t{f.state_count()} * tuples.parts.size());
  f.state_names.clear();
  f.state_names.reserve(f.state_count());
  for (StateId s = 0; s < f.state_count(); ++s) f.state_names.push_back(tuples.name(s));
}

swarmcheck::supervisor::Automaton decompile(const Fsm& f) {
  SWARM_DEMAND(f.named());
  swarmcheck::supervisor::Automaton a;
  a.states = f.state_names;
  for (EventId e = 0; e < f.event_count(); ++e)
    a.events[f.event_names[e]] = {f.controllable[e] != 0, f.observable[e] != 0};
  for (StateId s = 0; s < f.state_count(); ++s) {
    if (f.marked[s]) a.marked.insert(f.state_names[s]);
    for (auto i = f.first_edge[s]; i < f.first_edge[s + 1]; ++i)
      a.delta[f.state_names[s]][f.event_names[f.edge_event[i]]] =
          f.state_names[f.edge_target[i]];
  }
  return a;
}

Fsm restrict_states(const Fsm& f, const std::vector<std::uint8_t>& keep,
                    std::vector<StateId>* old_ids) {
  SWARM_DEMAND(keep.size() == f.marked.size());
  if (old_ids) old_ids->clear();
  Fsm out;
  out.event_names = f.event_names;
  out.controllable = f.controllable;
  out.observable = f.observable;
  if (f.state_count() == 0 || !keep[0]) {
    out.first_edge.assign(1, 0);
    return out;
  }
  std::vector<StateId> renumber(f.state_count(), kNoState);
  for (StateId s = 0; s < f.state_count(); ++s) {
    if (!keep[s]) continue;
    renumber[s] = out.state_count();
    if (f.named()) out.state_names.push_back(f.state_names[s]);
    out.marked.push_back(f.marked[s]);
    if (old_ids) old_ids->push_back(s);
  }
  out.first_edge.assign(out.marked.size() + 1, 0);
  for (StateId s = 0; s < f.state_count(); ++s) {
    if (!keep[s]) continue;
    for (auto i = f.first_edge[s]; i < f.first_edge[s + 1]; ++i) {
      if (!keep[f.edge_target[i]]) continue;
      out.edge_event.push_back(f.edge_event[i]);
      out.edge_target.push_back(renumber[f.edge_target[i]]);
    }
    out.first_edge[renumber[s] + 1] = static_cast<std::uint32_t>(out.edge_event.size());
  }
  return out;
}

}  // namespace swarmcheck::impl::supervisor
