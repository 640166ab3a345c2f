// The planning cost model: evaluation of a path of the FSM.
#include "spec/mission/plan.hpp"

#include <algorithm>

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
      travel[mn.robot] += distance(pos[mn.robot], m.tasks[mn.target].at);
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

}  // namespace swarmcheck::mission
