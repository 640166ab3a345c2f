// Execution of a mission in simulation (spec/mission/run.hpp): choice by the exact planner,
// motion, region entries. The public run_mission is defined here.

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <deque>
#include <optional>
#include <stdexcept>

#include "impl/mission/planner.hpp"
#include "spec/exploration/body.hpp"
#include "spec/exploration/controller.hpp"
#include "spec/mission/avoidance.hpp"
#include "spec/mission/plan.hpp"
#include "spec/mission/run.hpp"
#include "spec/mission/sensing.hpp"
#include "spec/mission/separation.hpp"
#include "spec/mission/steering.hpp"
#include "spec/mission/world.hpp"
#include "swarmcheck/mission.hpp"

namespace swarmcheck::impl::mission {

namespace {

namespace sm = swarmcheck::mission;
namespace ex = swarmcheck::exploration;
using sm::BodyModel;
using sm::EventRecord;
using sm::RunObserver;
using sm::RunOptions;
using sm::RunResult;
using sm::StepRecord;

struct RobotSim {
  sm::Point pos;
  double theta = 0.0;
  ex::ControllerState ctrl = ex::initial_controller();
  std::deque<std::size_t> queue;        // tasks to drive to, front first
  bool driving = false;                 // on a leg (the controller accepted its waypoint)
  sm::Point leg{};                      // the leg's waypoint: the front task, or a detour point
  bool leg_is_task = false;             // the leg's goal is the front task
  std::deque<sm::Point> route;          // in a world: the leg's waypoints after this one
  bool following = false;               // driving to a later waypoint of the route
  std::optional<std::size_t> last_task; // the task it was sent to last
  double planned = 0.0;                 // the cost model's travel of the tasks it was sent to
  double travelled = 0.0;
  bool blocked = false;
  bool yielded = false;                 // kept its state: its move would overlap another robot
  std::size_t yielded_to = 0;           // ... the robot it yielded to
  bool stuck = false;                   // ... in a standoff, finding no way aside
  std::optional<sm::IntervalRecord> interval;  // its activity so far
  std::vector<char> map;                // with unknown obstacles: its own map, and its
  std::vector<char> trav;               //   traversable cells on it
};

struct Proposal {
  sm::Point pos;
  double theta;
  ex::ControllerState ctrl;
  bool driving;
  bool arrived;
};

// Robot r's move towards `target`, on a leg already taken (`driving`) or a new one.
Proposal propose(const RunOptions& o, const ex::RobotParams& rp, const RobotSim& r,
                 const sm::Point& target, bool driving) {
  Proposal p{r.pos, r.theta, r.ctrl, driving, false};
  if (o.body == BodyModel::kinematic) {
    const double d = sm::distance(r.pos, target);
    const double step = o.speed_m_per_s * o.dt_s;
    p.driving = true;
    if (d <= step) {
      p.pos = target;
      p.arrived = true;
    } else {
      p.pos = {r.pos[0] + (target[0] - r.pos[0]) * (step / d),
               r.pos[1] + (target[1] - r.pos[1]) * (step / d)};
    }
    return p;
  }
  ex::ControllerInputs in{ex::BodyState{r.pos[0], r.pos[1], r.theta}, target, driving ? 0 : 1, o.dt_s};
  p.ctrl = ex::controller_step(rp, r.ctrl, in);
  const ex::BodyState b =
      ex::body_step(rp, in.pose, p.ctrl.servo_left, p.ctrl.servo_right, o.dt_s);
  p.pos = {b.x_m, b.y_m};
  p.theta = b.theta_rad;
  if (!driving && p.ctrl.on_destination_output == 0) p.driving = true;
  if (driving && p.ctrl.on_destination_output == 1) p.arrived = true;
  return p;
}

Proposal propose(const RunOptions& o, const ex::RobotParams& rp, const RobotSim& r) {
  return propose(o, rp, r, r.leg, r.driving);
}

class Runner {
 public:
  Runner(const sm::Mission& m, const RunOptions& o, RunObserver* obs)
      : m_(m), o_(o), obs_(obs), planner_(m), state_(m.initial_state) {
    sensing_ = m.world && !m.world->hidden.empty();
    if (sensing_) truth_ = sm::true_world(*m.world);
    for (std::size_t i = 0; i < m.robots.size(); ++i) {
      RobotSim sim;
      sim.pos = m.robots[i].start;
      if (sensing_) {
        sim.map = m.world->occupied;
        sim.trav = m.world->traversable[i];
      }
      robots_.push_back(std::move(sim));
    }
  }

  RunResult run() {
    for (const auto& e : sm::initial_entries(m_)) fire(e, 0.0);
    const auto first = ask();
    result_.makespan_planned = first.found ? first.cost.makespan : 0.0;
    if (first.found) plan_ = first.events;
    for (const auto& r : robots_) where_.push_back(r.pos);
    result_.clearance_min_m = sm::kNoClearance;
    check_apart(0.0);
    step_record(0.0);
    double t = 0.0;
    const auto steps_max = static_cast<long long>(o_.max_time_s / o_.dt_s);
    for (long long k = 0;; ++k) {
      if (!choose(t)) break;
      if (sm::is_marked(m_, state_)) {
        result_.completed = true;
        result_.reason = "mission complete";
        break;
      }
      if (k >= steps_max) {
        result_.reason = fmt::format("time limit of {} s reached", o_.max_time_s);
        break;
      }
      const double before = t;
      t = static_cast<double>(k + 1) * o_.dt_s;
      const bool progress = move(before, t, static_cast<std::uint64_t>(k));
      check_apart(t);
      if (!progress) {
        result_.reason = deadlock_reason();
        break;
      }
      step_record(t);
    }
    result_.final_state = state_;
    result_.time_s = t;
    for (const auto& r : robots_) result_.travel.push_back(r.travelled);
    for (const auto& r : robots_)
      if (r.interval) report(*r.interval);
    result_.plan_cache_hits = planner_.cache_hits();
    return result_;
  }

 private:
  sm::Point plan_point(std::size_t i) const {
    const auto& last = robots_[i].last_task;
    return last ? m_.tasks[*last].at : m_.robots[i].start;
  }

  sm::PlanQuery query() const {
    sm::PlanQuery q;
    q.from = state_;
    for (std::size_t i = 0; i < robots_.size(); ++i) {
      q.positions.push_back(plan_point(i));
      q.travel.push_back(robots_[i].planned);
    }
    return q;
  }

  sm::Plan ask() {
    if (asked_) ++result_.replans;
    asked_ = true;
    fresh_plan_ = true;
    return planner_.plan(query());
  }

  bool has_controllable() const {
    for (const auto& e : swarmcheck::supervisor::enabled(m_.fsm, state_))
      if (m_.fsm.events.at(e).controllable) return true;
    return false;
  }

  bool reaches_marked(const std::vector<std::string>& events) const {
    const auto end = sm::fire_all(m_, state_, events);
    return end && sm::is_marked(m_, *end);
  }

  // The plan's event to issue now and the plan after it (spec rule 1b), or nothing.
  std::optional<std::pair<std::string, std::vector<std::string>>> issuable() const {
    const auto& p = *plan_;
    std::vector<std::uint8_t> seen(robots_.size(), 0);  // robots with an earlier event in p
    std::vector<std::string> rest;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const std::size_t robot = m_.events.at(p[i]).robot;
      const bool first_own = !seen[robot];
      seen[robot] = 1;
      if (!first_own || !m_.fsm.events.at(p[i]).controllable) continue;
      const auto after = swarmcheck::supervisor::successor(m_.fsm, state_, p[i]);
      if (!after) continue;
      rest.assign(p.begin(), p.begin() + static_cast<std::ptrdiff_t>(i));
      rest.insert(rest.end(), p.begin() + static_cast<std::ptrdiff_t>(i) + 1, p.end());
      const auto end = sm::fire_all(m_, *after, rest);
      if (end && sm::is_marked(m_, *end)) return std::make_pair(p[i], std::move(rest));
      // The same tasks per robot, interleaved another way the supervisor allows from here.
      if (auto other = sm::path_with_assignment(m_, *after, sm::task_sequences(m_, rest)))
        return std::make_pair(p[i], std::move(*other));
    }
    return std::nullopt;
  }

  // Issues every controllable event the plan schedules and the supervisor allows now (spec rule
  // 1); false when the run must stop.
  bool choose(double t) {
    while (!sm::is_marked(m_, state_) && has_controllable()) {
      if (!fresh_plan_ || !plan_) {
        const sm::PlanQuery q = query();
        const sm::Plan p = ask();
        if (!p.found) {
          result_.reason = "no marked state is reachable from state " + state_;
          return false;
        }
        // The plan in hand is kept unless the new optimum is strictly better.
        if (!plan_ || sm::better(p.cost, sm::evaluate_path(m_, q, *plan_).cost)) {
          plan_ = p.events;
          settled_ = false;
        }
      }
      if (settled_) break;  // nothing changed since the last choice found nothing to issue
      auto next = issuable();
      if (!next) {
        settled_ = true;
        break;
      }
      const std::string e = next->first;
      plan_ = std::move(next->second);
      plan_->insert(plan_->begin(), e);
      const sm::Meaning& mn = m_.events.at(e);
      RobotSim& r = robots_[mn.robot];
      r.planned += sm::travel_cost(m_, mn.robot, plan_point(mn.robot), m_.tasks[mn.target].at);
      r.queue.push_back(mn.target);
      r.last_task = mn.target;
      fire(e, t);
    }
    return true;
  }

  void report(const sm::IntervalRecord& rec) {
    if (obs_) obs_->on_interval(rec);
    result_.intervals.push_back(rec);
  }

  // Extends each robot's activity interval over (from, to], or closes it and opens another.
  void account(const std::vector<sm::Activity>& did, double from, double to) {
    for (std::size_t i = 0; i < robots_.size(); ++i) {
      auto& open = robots_[i].interval;
      if (open && open->activity == did[i]) {
        open->to_s = to;
        continue;
      }
      if (open) report(*open);
      open = sm::IntervalRecord{m_.robots[i].name, did[i], from, to};
    }
  }

  // One step of motion; false when nothing could move and no event fired (deadlock).
  bool move(double before, double t, std::uint64_t step) {
    bool progress = false;
    const auto waited = waits();
    std::vector<sm::Activity> did(robots_.size(), sm::Activity::waiting_for_task);
    for (std::size_t i = 0; i < robots_.size(); ++i) {
      RobotSim& r = robots_[i];
      r.blocked = false;
      r.yielded = false;
      r.stuck = false;
      if (r.queue.empty()) continue;
      if (sensing_) learn(i, sm::scan_cells(truth_, r.pos, o_.seed, step, i));
      if (!r.driving && !r.following) start_leg(i);
      Proposal p = propose(o_, rp_, r);
      if (sensing_ && sm::overlaps_obstacle(truth_, p.pos, m_.robots[i].radius)) {  // a bump
        ++result_.bumps;
        did[i] = sm::Activity::busy;
        progress = learn(i, sm::overlapped_cells(truth_, p.pos, m_.robots[i].radius)) || progress;
        continue;
      }
      if (m_.world && sm::overlaps_obstacle(*m_.world, p.pos, m_.robots[i].radius))
        throw std::logic_error(fmt::format("robot {} would overlap an obstacle at [{}, {}] at t = {} s",
                                           m_.robots[i].name, p.pos[0], p.pos[1], t));
      std::optional<sm::Point> detour;  // a standoff's detour point (spec/mission/steering.hpp)
      if (const auto j = sm::yields_to(m_, i, r.pos, p.pos, ways())) {
        const bool cornered = sm::standoff(i, *j, ways());
        if (cornered) detour = steer(i, p);
        if (!detour) {
          r.yielded = true;
          r.yielded_to = *j;
          r.stuck = cornered;
          ++result_.yields;
          did[i] = sm::Activity::waiting_for_robot;
          continue;
        }
      }
      const auto entries = sm::entry_events(m_, i, r.pos, p.pos);
      if (!sm::fire_all(m_, state_, entries)) {
        r.blocked = true;
        did[i] = sm::Activity::waiting_for_supervisor;
        continue;
      }
      did[i] = sm::Activity::busy;
      progress = true;
      if (detour) {  // a fresh leg to the detour point; arrived, the robot routes anew
        ++result_.steers;
        r.leg = *detour;
        r.leg_is_task = false;
        r.route.clear();
        r.following = false;
      }
      r.travelled += sm::distance(r.pos, p.pos);
      r.pos = p.pos;
      where_[i] = p.pos;
      r.theta = p.theta;
      r.ctrl = p.ctrl;
      r.driving = p.driving;
      if (p.arrived && !r.route.empty()) {  // on to the route's next waypoint
        r.leg = r.route.front();
        r.route.pop_front();
        r.following = true;
        r.driving = false;
      } else if (p.arrived) {
        if (r.leg_is_task) r.queue.pop_front();
        r.driving = false;
        r.following = false;
      }
      for (const auto& e : entries) fire(e, t);
    }
    account(did, before, t);
    // A change in who yields to whom is progress too: a standoff seen now lets a robot steer
    // in the next step (spec/mission/steering.hpp).
    return progress || waits() != waited;
  }

  // Per robot, the robot it yielded to at its last turn to move and whether it was stuck, if it did.
  std::vector<std::optional<std::pair<std::size_t, bool>>> waits() const {
    std::vector<std::optional<std::pair<std::size_t, bool>>> out;
    for (const auto& r : robots_)
      out.push_back(r.yielded ? std::optional(std::make_pair(r.yielded_to, r.stuck)) : std::nullopt);
    return out;
  }

  // Robot i's first detour point whose move passes rule 3's checks (the world, the yield
  // test), with that move in p; nothing when none does.
  std::optional<sm::Point> steer(std::size_t i, Proposal& p) const {
    const RobotSim& r = robots_[i];
    const double radius = m_.robots[i].radius;
    sm::SteerView view{where_};
    if (m_.world) {
      view.map = sensing_ ? &r.map : &m_.world->occupied;
      view.traversable = sensing_ ? &r.trav : &m_.world->traversable[i];
    }
    const auto w = ways();
    for (const sm::Point& e : sm::steer_candidates(m_, i, r.pos, r.leg, view)) {
      const Proposal q = propose(o_, rp_, r, e, false);
      if (m_.world && sm::overlaps_obstacle(sensing_ ? truth_ : *m_.world, q.pos, radius)) continue;
      if (sm::yields_to(m_, i, r.pos, q.pos, w)) continue;
      p = q;
      return e;
    }
    return std::nullopt;
  }

  // The next leg of robot i: its front task, unless the current plan has the robot enter a
  // region first that does not contain that task and that it is not in; then the point of that
  // region nearest to it, a margin inside (so that the FSM's expected entry happens).
  void start_leg(std::size_t i) {
    RobotSim& r = robots_[i];
    const sm::Point task = m_.tasks[r.queue.front()].at;
    r.leg = task;
    r.leg_is_task = true;
    if (!plan_) {
      const sm::Plan p = ask();
      if (p.found) {
        plan_ = p.events;
        settled_ = false;
      }
    }
    const sm::Region* region = plan_ ? detour(i, task) : nullptr;
    if (region) {
      for (std::size_t k = 0; k < 2; ++k) {
        const double margin = std::min(0.5, (region->hi[k] - region->lo[k]) / 4);
        r.leg[k] = std::clamp(r.pos[k], region->lo[k] + margin, region->hi[k] - margin);
      }
      r.leg_is_task = false;
    }
    r.route.clear();
    if (!m_.world) return;
    // In a world the leg follows the A* route (a region's goal is the route's end); no route:
    // straight to the goal.
    const auto& trav = sensing_ ? r.trav : m_.world->traversable[i];
    const auto route = region ? sm::route_to_region(*m_.world, trav, r.pos, *region)
                              : sm::route_to_point(*m_.world, trav, r.pos, r.leg);
    if (!route) return;
    r.leg = route->waypoints.front();
    r.route.assign(route->waypoints.begin() + 1, route->waypoints.end());
  }

  // Cells new on robot i's map (spec/mission/sensing.hpp) restart its leg on it; false when
  // none was new.
  bool learn(std::size_t i, const std::vector<std::size_t>& cells) {
    RobotSim& r = robots_[i];
    if (!sm::add_to_map(r.map, cells)) return false;
    r.trav = sm::traversable_on(*m_.world, r.map, m_.robots[i].radius);
    ++result_.replans_sensed;
    r.driving = false;
    r.following = false;
    r.route.clear();
    return true;
  }

  // The region robot i must enter first by the plan, if it holds neither the task nor the robot.
  const sm::Region* detour(std::size_t i, const sm::Point& task) const {
    const RobotSim& r = robots_[i];
    for (const auto& e : *plan_) {
      const sm::Meaning& mn = m_.events.at(e);
      if (mn.robot != i) continue;
      if (mn.kind != sm::MeaningKind::region_entry) return nullptr;
      const sm::Region& g = m_.regions[mn.target];
      if (sm::inside(g, task) || sm::inside(g, r.pos)) return nullptr;
      return &g;
    }
    return nullptr;
  }

  std::string deadlock_reason() const {
    std::vector<std::string> why;
    for (std::size_t i = 0; i < robots_.size(); ++i)
      if (robots_[i].blocked) {
        const Proposal p = propose(o_, rp_, robots_[i]);
        for (const auto& e : sm::entry_events(m_, i, robots_[i].pos, p.pos))
          if (!swarmcheck::supervisor::successor(m_.fsm, state_, e))
            why.push_back(fmt::format("robot {} waits to fire {}", m_.robots[i].name, e));
      }
    std::string enabled;
    for (const auto& e : swarmcheck::supervisor::enabled(m_.fsm, state_))
      enabled += (enabled.empty() ? "" : ", ") + e;
    std::string out = fmt::format("deadlock in state {}: no robot can move (enabled events: {})",
                                  state_, enabled.empty() ? "none" : enabled);
    for (const auto& w : why) out += "; " + w;
    for (std::size_t i = 0; i < robots_.size(); ++i)
      if (robots_[i].yielded)
        out += fmt::format("; robot {} yields to robot {}", m_.robots[i].name,
                           m_.robots[robots_[i].yielded_to].name);
    return out;
  }

  void fire(const std::string& e, double t) {
    const auto next = swarmcheck::supervisor::successor(m_.fsm, state_, e);
    // Only enabled events fire: a planned one that is not is a bug of the planner (exit 3).
    if (!next) throw std::logic_error("planned event " + e + " is not enabled in state " + state_);
    state_ = *next;
    fresh_plan_ = false;
    settled_ = false;
    if (plan_) {  // the plan loses e, or is dropped when the rest is no longer a plan from here
      const auto at = std::find(plan_->begin(), plan_->end(), e);
      if (at == plan_->end()) {
        plan_.reset();
      } else {
        plan_->erase(at);
        if (!reaches_marked(*plan_)) plan_.reset();
      }
    }
    const sm::Meaning& mn = m_.events.at(e);
    EventRecord rec{t, e, m_.robots[mn.robot].name, m_.fsm.events.at(e).controllable, state_};
    if (obs_) obs_->on_event(rec);
    result_.events.push_back(std::move(rec));
  }

  std::vector<sm::RobotWay> ways() const {
    std::vector<sm::RobotWay> out;
    out.reserve(robots_.size());
    for (const auto& r : robots_)
      out.push_back({r.pos, !r.queue.empty(), r.leg,
                     r.yielded ? std::optional<std::size_t>(r.yielded_to) : std::nullopt, r.stuck});
    return out;
  }

  // No two robots overlap after a step (the yield rule guarantees it; a failure is a bug).
  void check_apart(double t) {
    const double c = sm::clearance_m(m_, where_);
    if (!(c >= 0.0)) throw std::logic_error(fmt::format("two robots overlap at t = {} s", t));
    result_.clearance_min_m = std::min(result_.clearance_min_m, c);
  }

  void step_record(double t) {
    if (!obs_) return;
    StepRecord s{t, state_, {}, {}, {}};
    for (const auto& r : robots_) {
      s.positions.push_back(r.pos);
      s.blocked.push_back(r.blocked);
      s.yielded.push_back(r.yielded);
    }
    obs_->on_step(s);
  }

  const sm::Mission& m_;
  RunOptions o_;
  RunObserver* obs_;
  ex::RobotParams rp_{};
  Planner planner_;
  std::string state_;
  std::optional<std::vector<std::string>> plan_;  // the current plan's events not yet fired
  bool asked_ = false;                            // the planner was asked at least once
  bool fresh_plan_ = false;                       // asked since the last event fired
  bool settled_ = false;  // the choice found nothing to issue, and no event fired since
  std::vector<RobotSim> robots_;
  std::vector<sm::Point> where_;  // the robots' positions, kept with RobotSim::pos
  bool sensing_ = false;          // the world has unknown obstacles: robots scan and re-route
  sm::GridWorld truth_;           // ... and the world as it is
  RunResult result_;
};

}  // namespace

}  // namespace swarmcheck::impl::mission

namespace swarmcheck::mission {

RunResult run_mission(const Mission& m, const RunOptions& o, RunObserver* observer) {
  return impl::mission::Runner(m, o, observer).run();
}

}  // namespace swarmcheck::mission
