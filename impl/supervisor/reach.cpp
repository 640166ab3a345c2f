// Accessibility and coaccessibility: one worklist pass each (forward over the CSR edges,
// backward over a reverse CSR built once).
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

std::vector<std::uint8_t> coaccessible_mask(const Fsm& f) {
  const StateId n = f.state_count();
  // Reverse adjacency as CSR: count in-degrees, prefix-sum, fill.
  std::vector<std::uint32_t> first(n + 1, 0);
  for (const StateId t : f.edge_target) ++first[t + 1];
  for (StateId s = 0; s < n; ++s) first[s + 1] += first[s];
  std::vector<StateId> source(f.edge_count());
  std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
  for (StateId s = 0; s < n; ++s)
    for (auto i = f.first_edge[s]; i < f.first_edge[s + 1]; ++i)
      source[fill[f.edge_target[i]]++] = s;
  std::vector<std::uint8_t> seen(n, 0);
  std::vector<StateId> stack;
  for (StateId s = 0; s < n; ++s)
    if (f.marked[s]) {
      seen[s] = 1;
      stack.push_back(s);
    }
  while (!stack.empty()) {
    const StateId t = stack.back();
    stack.pop_back();
    for (auto i = first[t]; i < first[t + 1]; ++i)
      if (!seen[source[i]]) {
        seen[source[i]] = 1;
        stack.push_back(source[i]);
      }
  }
  return seen;
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

}  // namespace swarmcheck::impl::supervisor
