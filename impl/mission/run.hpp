#pragma once
// Execution of a mission in simulation (DESIGN.md B5).
//
// Time 0: the region entries of the robots' start positions fire (spec::mission::initial_entries).
// Then, repeatedly:
//  1. Choice. While the state is not marked and enables a controllable event: plan exactly from
//     the state with the robots' positions (a robot's position is the task it was last sent to,
//     or its start if none; its committed travel is the straight-line distance still to go);
//     if the plan's first event is controllable, issue it (the supervisor takes it, the robot
//     queues the task) and choose again; else wait for the uncontrollable events.
//  2. Motion, robots in index order, one step of dt: a robot with a queued task proposes its
//     next pose (the foundation's controller_step then body_step, or a straight-line kinematic
//     mover); the regions the step enters fire their entry events in turn if the supervisor
//     enables them (spec::mission::avoidance), else the robot keeps its pose for this step.
//     A robot that arrives takes its next queued task.
// The run ends at a marked state ("mission complete"), or with the reason it cannot: no marked
// state reachable, a deadlock (a step in which no robot could move and no event fired), or the
// time limit.
#include <string>
#include <vector>

#include "spec/mission/mission.hpp"

namespace swarmcheck::impl::mission {

enum class BodyModel { unicycle, kinematic };

struct RunOptions {
  BodyModel body = BodyModel::unicycle;
  double dt_s = 0.05;
  double max_time_s = 3600.0;
  double speed_m_per_s = 0.5;  // kinematic body only
};

struct EventRecord {
  double time_s = 0.0;
  std::string event;
  std::string robot;
  bool controllable = false;
  std::string state_after;
};

struct StepRecord {
  double time_s = 0.0;
  std::string state;
  std::vector<spec::mission::Point> positions;
  std::vector<bool> blocked;  // kept its pose because an entry event was not enabled
};

class RunObserver {
 public:
  virtual ~RunObserver() = default;
  virtual void on_event(const EventRecord& e) = 0;
  virtual void on_step(const StepRecord& s) = 0;  // after time 0's events, then after each step
};

struct RunResult {
  bool completed = false;
  std::string reason;  // "mission complete" or why not
  std::string final_state;
  std::vector<EventRecord> events;
  double time_s = 0.0;
  std::vector<double> travel;      // per robot, metres actually driven
  double makespan_planned = 0.0;   // of the first plan
  std::size_t replans = 0;
  std::size_t plan_cache_hits = 0;
};

RunResult run_mission(const spec::mission::Mission& m, const RunOptions& o,
                      RunObserver* observer = nullptr);

}  // namespace swarmcheck::impl::mission
