#pragma once
// The planning cost model (DESIGN.md B4).
//
// A plan is a path of the FSM from a state to a marked state: a sequence of events, each enabled
// where it is taken. Only its controllable events are chosen; its uncontrollable events are
// waited for, and cost nothing. A controllable event starts a task: robot r's travel grows by the
// straight-line distance from where r then is (its position in the query, or the task it started
// last) to the task, or, in a mission with a world, by the length of the A* route around the
// obstacles (travel_cost, spec/mission/world.hpp), and r is then at that task. With travel_r the query's committed travel plus
// the plan's, the cost of a plan is
//     makespan = max_r travel_r,    total = sum_r travel_r (robots in index order),
// compared lexicographically: smaller makespan, then smaller total. Travel accumulates per robot
// in path order, so any two planners that find the same-cost plan agree to the bit.
#include <optional>
#include <string>
#include <vector>

#include "spec/mission/mission.hpp"

namespace swarmcheck::mission {

struct PlanQuery {
  std::string from;              // an FSM state
  std::vector<Point> positions;  // per robot: where it is, or will be once its current task ends
  std::vector<double> travel;    // per robot: travel already committed (>= 0)
};

// From the mission's initial state, robots at their starts, nothing travelled.
PlanQuery initial_query(const Mission& m);
// From state `from`, robots at their starts, nothing travelled.
PlanQuery query_from(const Mission& m, const std::string& from);

struct PlanCost {
  std::vector<double> travel;  // per robot
  double makespan = 0.0;
  double total = 0.0;
  friend bool operator==(const PlanCost&, const PlanCost&) = default;
};

PlanCost cost_of(std::vector<double> travel);
// a is strictly better than b: smaller makespan, or equal makespan and smaller total.
bool better(const PlanCost& a, const PlanCost& b);

struct Plan {
  bool found = false;                 // false: no marked state is reachable from the query's state
  std::vector<std::string> events;    // in order
  std::string final_state;            // a marked state when found
  PlanCost cost;
};

bool is_marked(const Mission& m, const std::string& q);

// Follows `events` from q.from under the cost model. error is empty when every event is enabled
// where it is taken and the path ends at a marked state; otherwise it says which rule broke.
struct PathEvaluation {
  std::string error;
  std::string final_state;
  PlanCost cost;
};
PathEvaluation evaluate_path(const Mission& m, const PlanQuery& q,
                             const std::vector<std::string>& events);

// The tasks each robot starts along `events`, in order (indices into m.tasks).
std::vector<std::vector<std::size_t>> task_sequences(const Mission& m,
                                                     const std::vector<std::string>& events);

// A path of the FSM from `from` to a marked state whose task starts are, robot by robot, exactly
// `tasks` (indices into m.tasks, in order); region entries are free. The shortest such path,
// found breadth first over (state, each robot's progress), events taken in name order at each
// state; nothing when there is none. Any such path has the cost of any other from one query
// (travel depends on each robot's own order only).
std::optional<std::vector<std::string>> path_with_assignment(
    const Mission& m, const std::string& from, const std::vector<std::vector<std::size_t>>& tasks);

}  // namespace swarmcheck::mission
