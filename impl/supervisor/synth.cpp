// Controllability and the supremal controllable nonblocking supervisor. The fixpoint of the spec
// (supcon_good + coaccessible within the candidates) is reached incrementally: a removed state
// removes its uncontrollable predecessors through a worklist, and each coaccessibility pass only
// walks states still kept. It stops when a pass removes nothing.
#include "impl/supervisor/operations.hpp"
#include "spec/util/demand.hpp"

namespace swarmcheck::impl::supervisor {

namespace {

struct Synthesis {
  Fsm p;                                   // plant || spec
  std::vector<std::uint8_t> unc_plant;     // [events of p]: uncontrollable and in the plant
  std::vector<std::uint8_t> bad;           // [states of p]: spec disables what plant must do
};

Synthesis prepare(const Fsm& plant, const Fsm& spec) {
  Synthesis s;
  std::vector<std::vector<StateId>> origin;
  s.p = product({&plant, &spec}, {"plant", "spec"}, &origin);
  const Fsm& p = s.p;
  s.unc_plant.assign(p.event_count(), 0);
  std::vector<EventId> in_p(plant.event_count());
  for (EventId e = 0; e < plant.event_count(); ++e) {
    in_p[e] = p.event_id(plant.event_names[e]);
    if (!plant.controllable[e]) s.unc_plant[in_p[e]] = 1;
  }
  s.bad.assign(p.state_count(), 0);
  for (StateId z = 0; z < p.state_count(); ++z) {
    const StateId x = origin[z][0];
    for (auto i = plant.first_edge[x]; i < plant.first_edge[x + 1]; ++i) {
      const EventId e = plant.edge_event[i];
      if (!plant.controllable[e] && p.successor(z, in_p[e]) == kNoState) s.bad[z] = 1;
    }
  }
  return s;
}

// Reverse adjacency of p as CSR; `only` filters edges by event.
struct Reverse {
  std::vector<std::uint32_t> first;
  std::vector<StateId> source;
};
Reverse reverse_edges(const Fsm& p, const std::vector<std::uint8_t>* only) {
  const StateId n = p.state_count();
  Reverse r;
  r.first.assign(n + 1, 0);
  auto take = [&](std::uint32_t i) { return !only || (*only)[p.edge_event[i]]; };
  for (StateId s = 0; s < n; ++s)
    for (auto i = p.first_edge[s]; i < p.first_edge[s + 1]; ++i)
      if (take(i)) ++r.first[p.edge_target[i] + 1];
  for (StateId s = 0; s < n; ++s) r.first[s + 1] += r.first[s];
  r.source.resize(r.first[n]);
  std::vector<std::uint32_t> fill(r.first.begin(), r.first.end() - 1);
  for (StateId s = 0; s < n; ++s)
    for (auto i = p.first_edge[s]; i < p.first_edge[s + 1]; ++i)
      if (take(i)) r.source[fill[p.edge_target[i]]++] = s;
  return r;
}

}  // namespace

bool is_controllable(const Fsm& plant, const Fsm& spec) {
  const Synthesis s = prepare(plant, spec);
  for (const auto b : s.bad)
    if (b) return false;
  return true;
}

Fsm supcon(const Fsm& plant, const Fsm& spec) {
  Synthesis s = prepare(plant, spec);
  const Fsm& p = s.p;
  const StateId n = p.state_count();
  const Reverse unc = reverse_edges(p, &s.unc_plant);
  const Reverse all = reverse_edges(p, nullptr);
  std::vector<std::uint8_t> removed(n, 0);
  std::vector<StateId> work;
  for (StateId z = 0; z < n; ++z)
    if (s.bad[z]) {
      removed[z] = 1;
      work.push_back(z);
    }
  std::vector<std::uint8_t> reach(n);
  std::vector<StateId> stack;
  for (;;) {
    while (!work.empty()) {  // removal closes over uncontrollable predecessors
      const StateId z = work.back();
      work.pop_back();
      for (auto i = unc.first[z]; i < unc.first[z + 1]; ++i)
        if (!removed[unc.source[i]]) {
          removed[unc.source[i]] = 1;
          work.push_back(unc.source[i]);
        }
    }
    std::fill(reach.begin(), reach.end(), 0);
    for (StateId z = 0; z < n; ++z)
      if (p.marked[z] && !removed[z]) {
        reach[z] = 1;
        stack.push_back(z);
      }
    while (!stack.empty()) {  // coaccessible through kept states only
      const StateId t = stack.back();
      stack.pop_back();
      for (auto i = all.first[t]; i < all.first[t + 1]; ++i) {
        const StateId w = all.source[i];
        if (!removed[w] && !reach[w]) {
          reach[w] = 1;
          stack.push_back(w);
        }
      }
    }
    for (StateId z = 0; z < n; ++z)
      if (!removed[z] && !reach[z]) {
        removed[z] = 1;
        work.push_back(z);
      }
    if (work.empty()) break;
  }
  std::vector<std::uint8_t> keep(n);
  for (StateId z = 0; z < n; ++z) keep[z] = removed[z] ? 0 : 1;
  return accessible_part(restrict_states(p, keep));
}

}  // namespace swarmcheck::impl::supervisor
