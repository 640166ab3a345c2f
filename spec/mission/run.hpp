#pragma once
// Execution of a mission in simulation (DESIGN.md B5): the options, the records and the result of
// a run, and the rules every runner follows. The library's runner (impl/mission/run.cpp) and the
// reference model (model/mission/run_model.cpp) both implement them; conformance/mission
// compares the two record for record, doubles by their bits.
//
// A robot has a pose (x, y, theta), a controller state, a queue of tasks (front first), a leg
// (its waypoint, and whether the waypoint is the front task), the task it was sent to last, its
// planned travel, the distance it travelled, and whether it was blocked in the last step. q is
// the FSM state; P is the current plan (its events not yet fired, a path of the FSM from q to a
// marked state), or none.
//
// Planned travel (the plan's cost model, spec/mission/plan.hpp, applied to what was issued): 0,
// plus, at each task start issued to the robot, the distance from its start or the task it was
// sent to before to the new task (the same additions in the same order as the planner makes, so
// the current plan's cost at a replan is the first plan's, bit for bit).
//
// The plan query at any moment: from q; per robot, the point of the task it was sent to last
// (its start if none) and its planned travel. Plans are exact (spec/mission/plan.hpp; among
// plans of equal cost the planner's own order decides, so a runner takes its planner as given).
// A query equal bit for bit to one remembered counts as a cache hit (plan_cache_hits); a new
// query is remembered, and when kPlanMemory are remembered already they are all forgotten first.
// Every query after the first plan counts as a replan (replans).
//
// Firing an event e (issued or entered): q moves on; P (if any) loses the first occurrence of e
// when what remains fires in turn from the new q to a marked state (fire_all, is_marked), and
// otherwise becomes none (e is not in P, or came in an order the rest of P cannot follow: a
// region entry the plan did not expect).
//
// Time 0: the entry events of the start positions fire (initial_entries); the first plan becomes
// P (none if no plan is found) and gives makespan_planned (0 if none); a step record at t = 0.
// Then for k = 0, 1, 2, ..., with t = 0 at first and then the t' of the step before:
//  1. Choice. While q is not marked and enables a controllable event:
//     a. When an event fired since the last query, or P is none: replan. No plan ends the run
//        ("no marked state is reachable from state q"). The new plan becomes P only when P is
//        none or the new plan's cost is strictly better (spec `better`) than P's cost from the
//        same query (evaluate_path): otherwise P, and with it the assignment, is kept.
//     b. Issue: the first event e = P[i] of P (in plan order) that is controllable, enabled in
//        q, and whose robot has no event before it in P, and after which the plan's assignment
//        can still be completed: with R = P without P[i], either R is a path from q' = delta(q,
//        e) to a marked state (e moved first, everything else in plan order), or else
//        path_with_assignment(q', task_sequences(R)) finds one (spec/mission/plan.hpp: the same
//        tasks per robot in the same order, so the same cost, events interleaved otherwise),
//        which replaces R. e is a task start: that robot queues the task and was sent to it
//        last, its planned travel grows, P becomes e followed by R, e fires at t (so P becomes
//        R), and the choice goes on. No such event: the choice stops (every robot whose next
//        planned event is uncontrollable, or not yet possible, waits while the others work).
//  2. End: q marked ends it ("mission complete"); k >= floor(max_time / dt) ends it ("time limit
//     of T s reached", T as fmt's {} prints max_time_s).
//  3. Motion to t' = (k + 1) dt (computed as the double (k + 1) times dt), robots in index order,
//     a robot without queued tasks idle. A robot with tasks and no leg starts one: its front task,
//     unless the plan P (when P is none, a plan is asked now and becomes P if found) has as this
//     robot's first own event the entry into a region that contains neither the task nor the
//     robot; then the point of that region nearest to it, a margin inside (per axis, its
//     coordinate clamped to [lo + m, hi - m], m = min(0.5, side / 4)).
//     It proposes a pose: `kinematic`, a straight line at speed_m_per_s, landing on the waypoint
//     when it is within one step; `unicycle`, the exploration controller_step then body_step
//     over dt (the waypoint's flag is 1 until the controller has taken it). In a world, a
//     proposal overlapping an obstacle is a bug (std::logic_error). If the robot must give way
//     (spec/mission/separation.hpp: yields_to, against the robots' current positions and ways,
//     those before it in index order already moved), it *yields*: it keeps its whole state,
//     fires nothing, and yields counts it; unless it is in a standoff and steers
//     (spec/mission/steering.hpp): then the steered proposal is its proposal, its leg the detour. Else, if the entry events
//     of the move (entry_events) do not all fire in turn from q, the robot is blocked and keeps
//     its whole state; otherwise it takes the proposal, travel grows by the distance moved, on
//     arrival at a task that task leaves its queue (and the leg ends), and the entry events fire
//     at t'. If no robot moved and no robot's yield (whom it yielded to, if anyone) changed,
//     the run ends in a deadlock, whose reason lists q's enabled events
//     and, per blocked robot, the entry events of its proposal q does not enable, then per
//     yielding robot (index order) "robot B yields to robot A" (A = the robot it yielded to).
//     After the step (the deadlocked one too), clearance_m of the positions must be >= 0 (else
//     std::logic_error: the rule was broken); clearance_min_m is its least value over the
//     positions at time 0 and after every motion step (+infinity with one robot).
//     Activity: over (t, t'] each robot is `busy` (it moved), `waiting for the supervisor` (it
//     has queued tasks and was blocked), `waiting for a robot` (it yielded) or `waiting for a
//     task` (no queued task). An interval is
//     a maximal run of steps of one robot with one activity; when a robot's activity changes,
//     its interval so far closes (to = t) and is reported, robots in index order, before the
//     step record. This is done for the deadlocked step too.
//  4. A step record at t'.
// At the end: final_state = q, time_s = the t' of the last motion step tried (0 if none; a
// deadlocked step counts), travel per robot, and the open intervals close at time_s and are
// reported, robots in index order (no motion step: no intervals).
#include <array>
#include <boost/hana.hpp>
#include <cstddef>
#include <cstdint>
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
      (double, speed_m_per_s),    // kinematic body only
      (std::uint64_t, seed));     // the range sensor's noise (spec/mission/sensing.hpp)
  RunOptions()
      : body(BodyModel::unicycle), dt_s(0.05), max_time_s(3600.0), speed_m_per_s(0.5), seed(1) {}
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
      (std::vector<bool>, blocked),   // kept its pose because an entry event was not enabled
      (std::vector<bool>, yielded));  // kept its pose because it would overlap another robot
};

// What a robot did over a step (rule 3): `busy` moved; the two kinds of waiting.
enum class Activity { busy, waiting_for_supervisor, waiting_for_task, waiting_for_robot };

struct IntervalRecord {
  BOOST_HANA_DEFINE_STRUCT(IntervalRecord,
      (std::string, robot),
      (Activity, activity),
      (double, from_s),
      (double, to_s));
};

class RunObserver {
 public:
  virtual ~RunObserver() = default;
  virtual void on_event(const EventRecord& e) = 0;
  virtual void on_step(const StepRecord& s) = 0;  // after time 0's events, then after each step
  virtual void on_interval(const IntervalRecord&) {}  // as each interval closes
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
      (std::size_t, plan_cache_hits),
      (std::vector<IntervalRecord>, intervals),   // in the order they closed
      (std::size_t, yields),             // robot-steps a robot yielded to another (rule 3)
      (std::size_t, replans_sensed),     // legs re-routed on a map the sensor changed
      (std::size_t, bumps),              // proposals held back by an unknown obstacle
      (std::size_t, steers),             // detours taken by local steering (steering.hpp)
      (double, clearance_min_m));        // least clearance_m of the step records (>= 0)
  RunResult()
      : completed(false), time_s(0.0), makespan_planned(0.0), replans(0), plan_cache_hits(0),
        yields(0), replans_sensed(0), bumps(0), steers(0), clearance_min_m(0.0) {}
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
template <>
struct EnumNames<swarmcheck::mission::Activity> {
  static constexpr std::array<std::pair<swarmcheck::mission::Activity, std::string_view>, 4> names{
      {{swarmcheck::mission::Activity::busy, "busy"},
       {swarmcheck::mission::Activity::waiting_for_supervisor, "waiting for the supervisor"},
       {swarmcheck::mission::Activity::waiting_for_task, "waiting for a task"},
       {swarmcheck::mission::Activity::waiting_for_robot, "waiting for a robot"}}};
};
}  // namespace swarmcheck::json_io
