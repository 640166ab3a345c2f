#pragma once
// The exact mission planner (DESIGN.md B4): the plan of least makespan, then least total travel,
// from any FSM state with the robots' current positions and committed travel.
//
// Method: best-first label setting over nodes (FSM state, each robot's position), a robot's
// position being its query position or one of the tasks. A label carries the per-robot travel
// vector; labels are popped in lexicographic (makespan, total, events, creation) order. Every
// event adds a non-negative amount to one robot's travel, so a popped label's key is never
// smaller than its parent's: the first label popped at a marked state is optimal. A label is
// dropped when a label already settled at its node has travel <= it robot by robot (Pareto
// dominance: every completion of the dropped label is matched by one no worse). Only states
// from which a marked state is reachable are entered.
//
// Caching (the thesis's future work): the compiled FSM, the reverse reachability to the marked
// states, the event meanings and the task-to-task distances are computed once per Planner; a
// plan is remembered per exact query (state, positions and travel, by bits), so re-planning at a
// choice whose inputs did not change is a lookup (up to the spec's kPlanMemory queries, forgotten
// all at once when full: spec/mission/run.hpp). The public swarmcheck::mission::Planner wraps this class.
#include <cstdint>
#include <map>
#include <tuple>
#include <string>
#include <vector>

#include "impl/supervisor/fsm.hpp"
#include "spec/mission/plan.hpp"

namespace swarmcheck::impl::mission {

using swarmcheck::mission::Plan;
using swarmcheck::mission::PlanQuery;

class Planner {
 public:
  explicit Planner(const swarmcheck::mission::Mission& m);

  // Throws InputError when q.from is not a state of the FSM or the vectors have the wrong size.
  Plan plan(const PlanQuery& q);

  std::size_t cache_hits() const { return cache_hits_; }
  std::size_t labels_last() const { return labels_last_; }  // labels created by the last search

 private:
  Plan search(const PlanQuery& q);
  // travel_cost of robot r from p to task t; remembered in a world (an A* search each).
  double cost_from(std::size_t r, const swarmcheck::mission::Point& p, std::size_t t);

  const swarmcheck::mission::Mission* mission_;
  supervisor::Fsm fsm_;
  std::map<std::string, supervisor::StateId> state_id_;
  std::vector<std::uint8_t> marked_;
  std::vector<std::uint8_t> coaccessible_;
  std::vector<std::int32_t> event_robot_;  // [event] robot of a task start, -1 otherwise
  std::vector<std::int32_t> event_task_;   // [event] task of a task start, -1 otherwise
  // travel_cost between two tasks of one robot, for the tasks it starts (a robot only ever moves
  // between its own tasks; a table over every task was robots x tasks^2, and 10 000 tasks that no
  // event names took 2.3 GB, and minutes in a world): robot r's tasks are numbered by task_slot_
  // [r * tasks + t], and the distance between slots a and b is at distance_at_[r] + a * n_r + b.
  std::vector<std::int32_t> task_slot_;
  std::vector<std::size_t> robot_task_count_;
  std::vector<std::size_t> distance_at_;
  std::vector<double> task_distance_;
  double task_distance(std::size_t r, std::size_t from_task, std::size_t to_task) const {
    const std::size_t tasks = task_slot_.size() / robot_task_count_.size();
    return task_distance_[distance_at_[r] + static_cast<std::size_t>(task_slot_[r * tasks + from_task]) * robot_task_count_[r] +
                          static_cast<std::size_t>(task_slot_[r * tasks + to_task])];
  }
  std::map<std::tuple<std::size_t, std::uint64_t, std::uint64_t, std::size_t>, double> route_memo_;
  std::map<std::string, Plan> cache_;
  std::size_t cache_hits_ = 0;
  std::size_t labels_last_ = 0;
};

}  // namespace swarmcheck::impl::mission
