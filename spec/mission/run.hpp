#pragma once
// Execution of a mission in simulation (DESIGN.md B5): the options, the records and the result of
// a run, and the rules every runner follows. The library's runner (impl/mission/run.cpp) and the
// reference model (model/mission/run_model.cpp) both implement them; conformance/mission
// compares the two record for record, doubles by their bits.
//
// A robot has a pose (x, y, theta), a controller state, a queue of tasks (front first), a leg
// (its waypoint, and whether the waypoint is the front task), the task it was sent to last, the
// distance it travelled, and whether it was blocked in the last step. q is the FSM state.
//
// The plan query at any moment: from q; per robot, the point of the task it was sent to last
// (its current position if none), and as committed travel the length of the straight lines from
// its current position through its queued tasks, in order. Plans are exact (spec/mission/plan.hpp;
// among plans of equal cost the planner's own order decides, so a runner takes its planner as
// given). A query equal bit for bit to one remembered counts as a cache hit (plan_cache_hits);
// a new query is remembered, and when kPlanMemory are remembered already they are all forgotten
// first.
//
// Time 0: the entry events of the start positions fire (initial_entries); the first plan gives
// makespan_planned (0 if none); a step record at t = 0. Then for k = 0, 1, 2, ..., with t = 0
// at first and then the t' of the step before:
//  1. Choice. While q is not marked and enables a controllable event: plan (one replan each);
//     no plan ends the run ("no marked state is reachable from state q"). If the plan's first
//     event is controllable, it is a task start: that robot queues the task and was sent to it
//     last, the event fires at t, and the choice goes on; otherwise it stops (wait).
//  2. End: q marked ends it ("mission complete"); k >= floor(max_time / dt) ends it ("time limit
//     of T s reached", T as fmt's {} prints max_time_s).
//  3. Motion to t' = (k + 1) dt (computed as the double (k + 1) times dt), robots in index order,
//     a robot without queued tasks idle. A robot with tasks and no leg starts one: its front task,
//     unless the plan asked now has as this robot's first own event the entry into a region that
//     contains neither the task nor the robot; then the point of that region nearest to it, a
//     margin inside (per axis, its coordinate clamped to [lo + m, hi - m], m = min(0.5, side / 4)).
//     It proposes a pose: `kinematic`, a straight line at speed_m_per_s, landing on the waypoint
//     when it is within one step; `unicycle`, the exploration controller_step then body_step
//     over dt (the waypoint's flag is 1 until the controller has taken it). If the entry events
//     of the move (entry_events) do not all fire in turn from q, the robot is blocked and keeps
//     its whole state; otherwise it takes the proposal, travel grows by the distance moved, on
//     arrival at a task that task leaves its queue (and the leg ends), and the entry events fire
//     at t'. If no robot moved, the run ends in a deadlock, whose reason lists q's enabled events
//     and, per blocked robot, the entry events of its proposal q does not enable.
//  4. A step record at t'.
// At the end: final_state = q, time_s = the t' of the last motion step tried (0 if none; a
// deadlocked step counts), travel per robot.
#include <array>
#include <boost/hana.hpp>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "spec/mission/mission.hpp"

namespace swarmcheck::mission {

enum class BodyModel { unicycle, kinematic };

// Distinct plan queries remembered for plan_cache_hits (see above).
inline constexpr std::size_t kPlanMemory = 4096;

struct RunOptions {
  BOOST_HANA_DEFINE_STRUCT(RunOptions,
      (BodyModel, body),
      (double, dt_s),
      (double, max_time_s),
      (double, speed_m_per_s));   // kinematic body only
  RunOptions() : body(BodyModel::unicycle), dt_s(0.05), max_time_s(3600.0), speed_m_per_s(0.5) {}
};

struct EventRecord {
  BOOST_HANA_DEFINE_STRUCT(EventRecord,
      (double, time_s),
      (std::string, event),
      (std::string, robot),
      (bool, controllable),
      (std::string, state_after));
};

struct StepRecord {
  BOOST_HANA_DEFINE_STRUCT(StepRecord,
      (double, time_s),
      (std::string, state),
      (std::vector<Point>, positions),
      (std::vector<bool>, blocked));  // kept its pose because an entry event was not enabled
};

class RunObserver {
 public:
  virtual ~RunObserver() = default;
  virtual void on_event(const EventRecord& e) = 0;
  virtual void on_step(const StepRecord& s) = 0;  // after time 0's events, then after each step
};

struct RunResult {
  BOOST_HANA_DEFINE_STRUCT(RunResult,
      (bool, completed),
      (std::string, reason),             // "mission complete" or why not
      (std::string, final_state),
      (std::vector<EventRecord>, events),
      (double, time_s),
      (std::vector<double>, travel),     // per robot, metres actually driven
      (double, makespan_planned),        // of the first plan
      (std::size_t, replans),
      (std::size_t, plan_cache_hits));
  RunResult() : completed(false), time_s(0.0), makespan_planned(0.0), replans(0), plan_cache_hits(0) {}
};

}  // namespace swarmcheck::mission

namespace swarmcheck::json_io {
template <class E>
struct EnumNames;
template <>
struct EnumNames<swarmcheck::mission::BodyModel> {
  static constexpr std::array<std::pair<swarmcheck::mission::BodyModel, std::string_view>, 2> names{
      {{swarmcheck::mission::BodyModel::unicycle, "unicycle"},
       {swarmcheck::mission::BodyModel::kinematic, "kinematic"}}};
};
}  // namespace swarmcheck::json_io
