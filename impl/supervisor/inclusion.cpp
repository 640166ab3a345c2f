// Language inclusion with shortest witnesses: breadth-first search over pairs of states.
#include <algorithm>
#include <unordered_map>

#include "impl/supervisor/operations.hpp"
#include "spec/util/demand.hpp"

namespace swarmcheck::impl::supervisor {

namespace {

constexpr std::uint32_t kNoParent = UINT32_MAX;

// A pair (state of a, state of b or kNoState), reached from `parent` by `event` (an id of a).
struct Node {
  StateId a, b;
  std::uint32_t parent;
  EventId event;
};

// The word that reaches node `at`, read back along the parents.
std::vector<std::string> word_to(const std::vector<Node>& nodes, std::uint32_t at, const Fsm& a) {
  std::vector<std::string> w;
  for (; nodes[at].parent != kNoParent; at = nodes[at].parent)
    w.push_back(a.event_names[nodes[at].event]);
  std::reverse(w.begin(), w.end());
  return w;
}

// For each event of a, its id in b (UINT32_MAX when b does not have it: no word of b uses it).
std::vector<EventId> events_in(const Fsm& a, const Fsm& b) {
  std::vector<EventId> out(a.event_count());
  for (EventId e = 0; e < a.event_count(); ++e) out[e] = b.event_id(a.event_names[e]);
  return out;
}

}  // namespace

swarmcheck::supervisor::Inclusion language_inclusion(const Fsm& a, const Fsm& b) {
  WorkBudget none;
  return language_inclusion(a, b, none, PeakModel{});
}

swarmcheck::supervisor::Inclusion language_inclusion(const Fsm& a, const Fsm& b, WorkBudget& budget, const PeakModel& peak) {
  swarmcheck::supervisor::Inclusion out;
  if (a.state_count() == 0) return out;  // L(a) is empty
  const std::vector<EventId> in_b = events_in(a, b);
  // Pair (x, y) -> node index; y = kNoState (b has left its language) is stored as b's count.
  const std::uint64_t width = std::uint64_t{b.state_count()} + 1;
  auto key = [&](StateId x, StateId y) {
    return std::uint64_t{x} * width + (y == kNoState ? b.state_count() : y);
  };
  std::unordered_map<std::uint64_t, std::uint32_t> index;
  std::vector<Node> nodes;
  auto visit = [&](StateId x, StateId y, std::uint32_t parent, EventId e) {
    if (index.emplace(key(x, y), static_cast<std::uint32_t>(nodes.size())).second)
      nodes.push_back(Node{x, y, parent, e});
  };
  visit(0, b.state_count() == 0 ? kNoState : 0, kNoParent, 0);
  // nodes doubles as the FIFO queue: breadth-first order is index order.
  // The pairs are up to |a| x (|b| + 1): quadratic, so budgeted.
  const auto check = [&](std::uint32_t at) {
    budget.check("a, b", peak.at(static_cast<double>(nodes.size()), 0), [&] {
      return "the comparison stopped after exploring " + std::to_string(at) + " pairs of states (" + std::to_string(nodes.size()) +
             " found, of up to " + std::to_string(std::uint64_t{a.state_count()} * width) + ")";
    });
  };
  for (std::uint32_t at = 0; at < nodes.size() && (out.closed || out.marked); ++at) {
    if (at % 4096 == 0) check(at);
    const Node n = nodes[at];
    if (n.b == kNoState && out.closed) {
      out.closed = false;
      out.closed_witness = word_to(nodes, at, a);
    }
    if (a.marked[n.a] && (n.b == kNoState || !b.marked[n.b]) && out.marked) {
      out.marked = false;
      out.marked_witness = word_to(nodes, at, a);
    }
    for (auto i = a.first_edge[n.a]; i < a.first_edge[n.a + 1]; ++i) {  // events in name order
      const EventId e = a.edge_event[i];
      const StateId y = n.b == kNoState || in_b[e] == UINT32_MAX ? kNoState : b.successor(n.b, in_b[e]);
      visit(a.edge_target[i], y, at, e);
    }
  }
  SWARM_ASSERT(nodes.size() <= std::uint64_t{a.state_count()} * width);
  budget.note(peak.at(static_cast<double>(nodes.size()), 0));
  return out;
}

}  // namespace swarmcheck::impl::supervisor
