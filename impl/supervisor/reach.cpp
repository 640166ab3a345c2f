// Accessibility and coaccessibility: one worklist pass each (forward over the CSR edges,
// backward over a reverse CSR built once).
#include "impl/supervisor/reach.hpp"

#include <algorithm>

#include "impl/supervisor/operations.hpp"
#include "spec/util/demand.hpp"

namespace swarmcheck::impl::supervisor {

std::vector<std::uint8_t> accessible_mask(const Fsm& f) {
  std::vector<std::uint8_t> seen(f.state_count(), 0);
  if (f.state_count() == 0) return seen;
  std::vector<StateId> stack{0};
  seen[0] = 1;
  while (!stack.empty()) {
    const StateId s = stack.back();
    stack.pop_back();
    for (auto i = f.first_edge[s]; i < f.first_edge[s + 1]; ++i) {
      const StateId t = f.edge_target[i];
      if (!seen[t]) {
        seen[t] = 1;
        stack.push_back(t);
      }
    }
  }
  return seen;
}

ReverseEdges reverse_edges(const Fsm& f, const std::vector<std::uint8_t>* events) {
  SWARM_DEMAND(!events || events->size() == f.event_count());
  const StateId n = f.state_count();
  auto take = [&](std::uint32_t i) { return !events || (*events)[f.edge_event[i]]; };
  // Count the kept in-degrees, prefix-sum them into offsets, then fill in source order.
  ReverseEdges r;
  r.first.assign(n + 1, 0);
  for (StateId s = 0; s < n; ++s)
    for (auto i = f.first_edge[s]; i < f.first_edge[s + 1]; ++i)
      if (take(i)) ++r.first[f.edge_target[i] + 1];
  for (StateId s = 0; s < n; ++s) r.first[s + 1] += r.first[s];
  r.source.resize(r.first[n]);
  std::vector<std::uint32_t> fill(r.first.begin(), r.first.end() - 1);
  for (StateId s = 0; s < n; ++s)
    for (auto i = f.first_edge[s]; i < f.first_edge[s + 1]; ++i)
      if (take(i)) r.source[fill[f.edge_target[i]]++] = s;
  return r;
}

std::vector<std::uint8_t> coreachable(const ReverseEdges& r, const std::vector<std::uint8_t>& seeds,
                                      const std::vector<std::uint8_t>* within) {
  const std::size_t n = seeds.size();
  SWARM_DEMAND(r.first.size() == n + 1);
  SWARM_DEMAND(!within || within->size() == n);
  auto inside = [&](StateId s) { return !within || (*within)[s]; };
  std::vector<std::uint8_t> seen(n, 0);
  // Breadth first (the vector is the FIFO): states found together sit close in a product's
  // breadth-first numbering, so the walk reads memory in runs rather than at random.
  std::vector<StateId> queue;
  for (StateId s = 0; s < n; ++s)
    if (seeds[s] && inside(s)) {
      seen[s] = 1;
      queue.push_back(s);
    }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const StateId t = queue[head];
    for (auto i = r.first[t]; i < r.first[t + 1]; ++i) {
      const StateId s = r.source[i];
      if (!seen[s] && inside(s)) {
        seen[s] = 1;
        queue.push_back(s);
      }
    }
  }
  return seen;
}

std::vector<std::uint8_t> coaccessible_mask(const Fsm& f) {
  return coreachable(reverse_edges(f), f.marked);
}

Fsm accessible_part(const Fsm& f) { return restrict_states(f, accessible_mask(f)); }

Fsm trim(const Fsm& f) {
  auto keep = accessible_mask(f);
  const auto coac = coaccessible_mask(f);
  for (std::size_t s = 0; s < keep.size(); ++s) keep[s] = keep[s] && coac[s];
  return restrict_states(f, keep);
}

std::vector<StateId> blocking_states(const Fsm& f) {
  const auto ac = accessible_mask(f);
  const auto coac = coaccessible_mask(f);
  std::vector<StateId> out;
  for (StateId s = 0; s < f.state_count(); ++s)
    if (ac[s] && !coac[s]) out.push_back(s);
  return out;
}

bool is_nonblocking(const Fsm& f) { return blocking_states(f).empty(); }

bool every_state_coaccessible(const Fsm& f) {
  const auto coac = coaccessible_mask(f);
  return std::all_of(coac.begin(), coac.end(), [](std::uint8_t c) { return c != 0; });
}

swarmcheck::supervisor::CheckReport check(const Fsm& f) {
  const auto ac = accessible_mask(f);
  const auto coac = coaccessible_mask(f);
  swarmcheck::supervisor::CheckReport r;
  for (StateId s = 0; s < f.state_count(); ++s) {
    if (!ac[s]) r.unreachable_states.push_back(f.state_names[s]);
    if (ac[s] && !coac[s]) r.blocking_states.push_back(f.state_names[s]);
    if (!coac[s]) r.coaccessible = false;
  }
  return r;
}

std::vector<EventId> shortlex_word(const Fsm& f, StateId target) {
  SWARM_DEMAND(target < f.state_count());
  std::vector<StateId> parent(f.state_count(), kNoState);
  std::vector<EventId> via(f.state_count(), 0);
  for (StateId s = 0; s < f.state_count() && parent[target] == kNoState && target != 0; ++s)
    for (auto i = f.first_edge[s]; i < f.first_edge[s + 1]; ++i) {
      const StateId t = f.edge_target[i];
      if (t != 0 && parent[t] == kNoState) {
        parent[t] = s;
        via[t] = f.edge_event[i];
      }
    }
  std::vector<EventId> word;
  for (StateId s = target; s != 0; s = parent[s]) {
    SWARM_DEMAND(parent[s] != kNoState);
    word.push_back(via[s]);
  }
  std::reverse(word.begin(), word.end());
  return word;
}

std::vector<std::string> event_names(const Fsm& f, const std::vector<EventId>& word) {
  std::vector<std::string> out;
  out.reserve(word.size());
  for (const EventId e : word) out.push_back(f.event_names[e]);
  return out;
}

}  // namespace swarmcheck::impl::supervisor
