// Brute-force planning: depth-first enumeration of node-simple walks.
#include "model/mission/brute_force.hpp"

#include <set>
#include <stdexcept>
#include <utility>

namespace swarmcheck::model::mission {

namespace {

namespace sm = swarmcheck::mission;

struct Search {
  const sm::Mission& m;
  const sm::PlanQuery& q;
  std::size_t max_walks;
  std::size_t walks = 0;
  std::vector<std::string> events;
  std::set<std::pair<std::string, std::vector<int>>> on_walk;
  sm::Plan best;

  void visit(const std::string& state, std::vector<int>& where) {
    if (++walks > max_walks) throw std::length_error("brute_force_plan: too many walks");
    if (sm::is_marked(m, state)) {
      const auto ev = sm::evaluate_path(m, q, events);
      if (!best.found || sm::better(ev.cost, best.cost)) {
        best.found = true;
        best.events = events;
        best.final_state = ev.final_state;
        best.cost = ev.cost;
      }
    }
    const auto it = m.fsm.delta.find(state);
    if (it == m.fsm.delta.end()) return;
    for (const auto& [event, target] : it->second) {
      std::vector<int> next = where;
      const auto mn = m.events.find(event);
      if (mn != m.events.end() && mn->second.kind == sm::MeaningKind::task_start)
        next[mn->second.robot] = static_cast<int>(mn->second.target);
      auto node = std::make_pair(target, next);
      if (on_walk.count(node)) continue;
      on_walk.insert(node);
      events.push_back(event);
      visit(target, next);
      events.pop_back();
      on_walk.erase(node);
    }
  }
};

}  // namespace

sm::Plan brute_force_plan(const sm::Mission& m, const sm::PlanQuery& q, std::size_t max_walks) {
  Search s{m, q, max_walks, 0, {}, {}, {}};
  std::vector<int> where(m.robots.size(), -1);
  s.on_walk.insert({q.from, where});
  s.visit(q.from, where);
  return s.best;
}

}  // namespace swarmcheck::model::mission
