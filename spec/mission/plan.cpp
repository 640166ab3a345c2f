// The planning cost model: evaluation of a path of the FSM.
#include "spec/mission/plan.hpp"

#include <algorithm>
#include <deque>
#include <map>
#include <utility>

#include "spec/mission/world.hpp"
#include "spec/supervisor/automaton.hpp"

namespace swarmcheck::mission {

PlanQuery query_from(const Mission& m, const std::string& from) {
  PlanQuery q;
  q.from = from;
  for (const auto& r : m.robots) q.positions.push_back(r.start);
  q.travel.assign(m.robots.size(), 0.0);
  return q;
}

PlanQuery initial_query(const Mission& m) { return query_from(m, m.initial_state); }

PlanCost cost_of(std::vector<double> travel) {
  PlanCost c;
  c.travel = std::move(travel);
  for (const double t : c.travel) {
    c.makespan = std::max(c.makespan, t);
    c.total += t;
  }
  return c;
}

bool better(const PlanCost& a, const PlanCost& b) {
  if (a.makespan != b.makespan) return a.makespan < b.makespan;
  return a.total < b.total;
}

bool is_marked(const Mission& m, const std::string& q) {
  return std::find(m.marked_states.begin(), m.marked_states.end(), q) != m.marked_states.end();
}

PathEvaluation evaluate_path(const Mission& m, const PlanQuery& q,
                             const std::vector<std::string>& events) {
  PathEvaluation out;
  std::vector<Point> pos = q.positions;
  std::vector<double> travel = q.travel;
  std::string state = q.from;
  for (std::size_t i = 0; i < events.size(); ++i) {
    const auto next = supervisor::successor(m.fsm, state, events[i]);
    if (!next) {
      out.error = "event " + std::to_string(i) + " (" + events[i] + ") is not enabled in state " +
                  state;
      return out;
    }
    const auto it = m.events.find(events[i]);
    if (it != m.events.end() && it->second.kind == MeaningKind::task_start) {
      const Meaning& mn = it->second;
      travel[mn.robot] += travel_cost(m, mn.robot, pos[mn.robot], m.tasks[mn.target].at);
      pos[mn.robot] = m.tasks[mn.target].at;
    }
    state = *next;
  }
  out.final_state = state;
  out.cost = cost_of(travel);
  if (!is_marked(m, state)) out.error = "the path ends in state " + state + ", which is not marked";
  return out;
}

std::vector<std::vector<std::size_t>> task_sequences(const Mission& m,
                                                     const std::vector<std::string>& events) {
  std::vector<std::vector<std::size_t>> out(m.robots.size());
  for (const auto& e : events) {
    const auto it = m.events.find(e);
    if (it != m.events.end() && it->second.kind == MeaningKind::task_start)
      out[it->second.robot].push_back(it->second.target);
  }
  return out;
}

std::optional<std::vector<std::string>> path_with_assignment(
    const Mission& m, const std::string& from, const std::vector<std::vector<std::size_t>>& tasks) {
  using Node = std::pair<std::string, std::vector<std::size_t>>;  // state, tasks started per robot
  std::map<Node, std::pair<Node, std::string>> parent;              // node -> (previous, event)
  const Node start{from, std::vector<std::size_t>(tasks.size(), 0)};
  std::deque<Node> open{start};
  parent.emplace(start, std::make_pair(start, std::string()));
  while (!open.empty()) {
    const Node n = open.front();
    open.pop_front();
    bool done = is_marked(m, n.first);
    for (std::size_t r = 0; r < tasks.size() && done; ++r) done = n.second[r] == tasks[r].size();
    if (done) {
      std::vector<std::string> path;
      for (Node at = n; at != start; at = parent.at(at).first) path.push_back(parent.at(at).second);
      std::reverse(path.begin(), path.end());
      return path;
    }
    for (const auto& e : supervisor::enabled(m.fsm, n.first)) {
      Node next{*supervisor::successor(m.fsm, n.first, e), n.second};
      const Meaning& mn = m.events.at(e);
      if (mn.kind == MeaningKind::task_start) {
        std::size_t& done_r = next.second[mn.robot];
        if (done_r == tasks[mn.robot].size() || tasks[mn.robot][done_r] != mn.target) continue;
        ++done_r;
      }
      if (parent.emplace(next, std::make_pair(n, e)).second) open.push_back(std::move(next));
    }
  }
  return std::nullopt;
}

}  // namespace swarmcheck::mission
