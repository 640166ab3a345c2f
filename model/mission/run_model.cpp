// The reference run: plain values and one function per rule of spec/mission/run.hpp.
#include "model/mission/run_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <bit>
#include <cstdint>
#include <optional>
#include <set>
#include <utility>

#include "spec/exploration/body.hpp"
#include "spec/exploration/controller.hpp"
#include "spec/mission/avoidance.hpp"
#include "spec/mission/sensing.hpp"
#include "spec/mission/separation.hpp"
#include "spec/mission/steering.hpp"
#include "spec/mission/world.hpp"
#include "spec/util/demand.hpp"

namespace swarmcheck::model::mission {

namespace {

namespace sm = swarmcheck::mission;
namespace ex = swarmcheck::exploration;

struct Robot {
  sm::Point pos{};
  double theta_rad = 0.0;
  ex::ControllerState controller = ex::initial_controller();
  std::vector<std::size_t> tasks;   // queued, front first
  bool on_leg = false;
  sm::Point waypoint{};
  bool waypoint_is_task = false;    // the leg's goal is the front task (else a region's point)
  std::vector<sm::Point> route;     // in a world: the leg's waypoints after this one
  bool following = false;           // driving to a later waypoint of the leg's route
  bool sent = false;                // sent to a task at least once
  std::size_t sent_to = 0;          // the task it was sent to last
  double planned_m = 0.0;           // the cost model's travel of the tasks it was sent to
  double travelled_m = 0.0;
  bool blocked = false;
  bool yielded = false;             // kept its state: its move would overlap another robot
  std::size_t yielded_to = 0;       // ... the robot it yielded to
  bool stuck = false;               // ... in a standoff, finding no way aside
  std::optional<sm::IntervalRecord> open;  // its activity interval so far
  std::vector<char> map;            // with unknown obstacles: its own map, and its traversable
  std::vector<char> trav;           //   cells on it
};

// One robot's proposed step.
struct Move {
  sm::Point pos;
  double theta_rad;
  ex::ControllerState controller;
  bool on_leg;
  bool arrived;
};

using QueryKey = std::pair<std::string, std::vector<std::uint64_t>>;  // state, doubles' bits

struct World {
  const sm::Mission& m;
  const sm::RunOptions& o;
  const PlanFunction& plan;
  sm::RunObserver* observer;
  std::string q;
  std::vector<Robot> robots;
  sm::RunResult result;
  std::set<QueryKey> remembered;    // for plan_cache_hits only
  std::optional<std::vector<std::string>> current;  // P: the current plan's events not yet fired
  bool asked = false;               // the planner was asked at least once
  bool asked_since_event = false;   // ... since the last event fired
  bool sensing = false;             // the world has unknown obstacles: robots scan and re-route
  sm::GridWorld truth;              // ... and the world as it is
};

// Where robot i is for planning: the task it was sent to last, else its start.
sm::Point plan_position(const World& w, std::size_t i) {
  const Robot& r = w.robots[i];
  return r.sent ? w.m.tasks[r.sent_to].at : w.m.robots[i].start;
}

sm::PlanQuery query(const World& w) {
  sm::PlanQuery out;
  out.from = w.q;
  for (std::size_t i = 0; i < w.robots.size(); ++i) {
    out.positions.push_back(plan_position(w, i));
    out.travel.push_back(w.robots[i].planned_m);
  }
  return out;
}

// Plans from the current query, counting it as a cache hit when it is remembered.
sm::Plan ask(World& w) {
  const sm::PlanQuery pq = query(w);
  QueryKey key{pq.from, {}};
  for (std::size_t r = 0; r < pq.positions.size(); ++r)
    for (const double v : {pq.positions[r][0], pq.positions[r][1], pq.travel[r]})
      key.second.push_back(std::bit_cast<std::uint64_t>(v));
  if (w.remembered.count(key)) {
    ++w.result.plan_cache_hits;
  } else {
    if (w.remembered.size() >= sm::kPlanMemory) w.remembered.clear();
    w.remembered.insert(std::move(key));
  }
  if (w.asked) ++w.result.replans;
  w.asked = true;
  w.asked_since_event = true;
  return w.plan(pq);
}

// The events left and whether they lead from q to a marked state.
bool leads_to_marked(const World& w, const std::string& q, const std::vector<std::string>& events) {
  const auto end = sm::fire_all(w.m, q, events);
  return end && sm::is_marked(w.m, *end);
}

void fire(World& w, const std::string& e, double t) {
  const auto next = swarmcheck::supervisor::successor(w.m.fsm, w.q, e);
  // The plan function is the caller's: an event it plans that q does not enable is its bug.
  if (!next) throw std::logic_error("the planner's event " + e + " is not enabled in state " + w.q);
  w.q = *next;
  w.asked_since_event = false;
  if (w.current) {
    auto& p = *w.current;
    const auto at = std::find(p.begin(), p.end(), e);
    if (at == p.end()) {
      w.current.reset();
    } else {
      p.erase(at);
      if (!leads_to_marked(w, w.q, p)) w.current.reset();
    }
  }
  sm::EventRecord rec;
  rec.time_s = t;
  rec.event = e;
  rec.robot = w.m.robots[w.m.events.at(e).robot].name;
  rec.controllable = w.m.fsm.events.at(e).controllable;
  rec.state_after = w.q;
  if (w.observer) w.observer->on_event(rec);
  w.result.events.push_back(rec);
}

std::vector<sm::Point> positions(const World& w) {
  std::vector<sm::Point> out;
  for (const Robot& r : w.robots) out.push_back(r.pos);
  return out;
}

std::vector<sm::RobotWay> ways(const World& w) {
  std::vector<sm::RobotWay> out;
  for (const Robot& r : w.robots)
    out.push_back({r.pos, !r.tasks.empty(), r.waypoint,
                   r.yielded ? std::optional<std::size_t>(r.yielded_to) : std::nullopt, r.stuck});
  return out;
}

// Rule 3's check after a step: no two robots overlap; the least clearance so far.
void check_apart(World& w, double t) {
  const double c = sm::clearance_m(w.m, positions(w));
  if (!(c >= 0.0)) throw std::logic_error(fmt::format("two robots overlap at t = {} s", t));
  w.result.clearance_min_m = std::min(w.result.clearance_min_m, c);
}

void record_step(const World& w, double t) {
  if (!w.observer) return;
  sm::StepRecord s;
  s.time_s = t;
  s.state = w.q;
  for (const Robot& r : w.robots) {
    s.positions.push_back(r.pos);
    s.blocked.push_back(r.blocked);
    s.yielded.push_back(r.yielded);
  }
  w.observer->on_step(s);
}

bool enables_controllable(const World& w) {
  for (const auto& e : swarmcheck::supervisor::enabled(w.m.fsm, w.q))
    if (w.m.fsm.events.at(e).controllable) return true;
  return false;
}

// Rule 1b: the event to issue now and the plan after it, or nothing.
std::optional<std::pair<std::string, std::vector<std::string>>> issuable(const World& w) {
  const std::vector<std::string>& p = *w.current;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!w.m.fsm.events.at(p[i]).controllable) continue;
    const auto after = swarmcheck::supervisor::successor(w.m.fsm, w.q, p[i]);
    if (!after) continue;
    const std::size_t robot = w.m.events.at(p[i]).robot;
    bool first_own = true;
    for (std::size_t j = 0; j < i; ++j) first_own = first_own && w.m.events.at(p[j]).robot != robot;
    if (!first_own) continue;
    std::vector<std::string> rest;
    for (std::size_t j = 0; j < p.size(); ++j)
      if (j != i) rest.push_back(p[j]);
    if (leads_to_marked(w, *after, rest)) return std::make_pair(p[i], rest);
    if (auto other = sm::path_with_assignment(w.m, *after, sm::task_sequences(w.m, rest)))
      return std::make_pair(p[i], std::move(*other));
  }
  return std::nullopt;
}

// Rule 1; false when the run ends (no marked state reachable).
bool choose(World& w, double t) {
  while (!sm::is_marked(w.m, w.q) && enables_controllable(w)) {
    if (!w.asked_since_event || !w.current) {
      const sm::PlanQuery pq = query(w);
      const sm::Plan p = ask(w);
      if (!p.found) {
        w.result.reason = "no marked state is reachable from state " + w.q;
        return false;
      }
      if (!w.current || sm::better(p.cost, sm::evaluate_path(w.m, pq, *w.current).cost))
        w.current = p.events;
    }
    auto next = issuable(w);
    if (!next) return true;
    const std::string e = next->first;
    w.current = std::move(next->second);
    w.current->insert(w.current->begin(), e);
    const sm::Meaning& start = w.m.events.at(e);
    Robot& r = w.robots[start.robot];
    r.planned_m +=
        sm::travel_cost(w.m, start.robot, plan_position(w, start.robot), w.m.tasks[start.target].at);
    r.tasks.push_back(start.target);
    r.sent = true;
    r.sent_to = start.target;
    fire(w, e, t);
  }
  return true;
}

// The region robot i must enter before its task, if the plan says so (rule 3), else nothing.
const sm::Region* detour_region(const World& w, const std::vector<std::string>& plan,
                                std::size_t i) {
  const Robot& r = w.robots[i];
  for (const auto& e : plan) {
    const sm::Meaning& mn = w.m.events.at(e);
    if (mn.robot != i) continue;
    if (mn.kind != sm::MeaningKind::region_entry) return nullptr;
    const sm::Region& g = w.m.regions[mn.target];
    const bool needed = !sm::inside(g, w.m.tasks[r.tasks.front()].at) && !sm::inside(g, r.pos);
    return needed ? &g : nullptr;
  }
  return nullptr;
}

// In a world, the leg follows the A* route to its goal (spec/mission/world.hpp); a region's goal
// is then the route's end, not the nearest point. No route: straight to the goal.
void route_leg(World& w, std::size_t i, const sm::Region* g) {
  Robot& r = w.robots[i];
  r.route.clear();
  if (!w.m.world) return;
  const auto& trav = w.sensing ? r.trav : w.m.world->traversable[i];
  const auto route = g ? sm::route_to_region(*w.m.world, trav, r.pos, *g)
                       : sm::route_to_point(*w.m.world, trav, r.pos, r.waypoint);
  if (!route) return;
  r.waypoint = route->waypoints.front();
  r.route.assign(route->waypoints.begin() + 1, route->waypoints.end());
}

void start_leg(World& w, std::size_t i) {
  Robot& r = w.robots[i];
  r.waypoint = w.m.tasks[r.tasks.front()].at;
  r.waypoint_is_task = true;
  if (!w.current) {
    const sm::Plan p = ask(w);
    if (p.found) w.current = p.events;
  }
  const sm::Region* g = w.current ? detour_region(w, *w.current, i) : nullptr;
  if (g) {
    for (std::size_t k = 0; k < 2; ++k) {
      const double margin = std::min(0.5, (g->hi[k] - g->lo[k]) / 4);
      r.waypoint[k] = std::clamp(r.pos[k], g->lo[k] + margin, g->hi[k] - margin);
    }
    r.waypoint_is_task = false;
  }
  route_leg(w, i, g);
}

Move propose(const World& w, const Robot& r) {
  Move mv{r.pos, r.theta_rad, r.controller, r.on_leg, false};
  if (w.o.body == sm::BodyModel::kinematic) {
    const double d = sm::distance(r.pos, r.waypoint);
    const double step = w.o.speed_m_per_s * w.o.dt_s;
    mv.on_leg = true;
    mv.arrived = d <= step;
    if (mv.arrived)
      mv.pos = r.waypoint;
    else
      mv.pos = {r.pos[0] + (r.waypoint[0] - r.pos[0]) * (step / d),
                r.pos[1] + (r.waypoint[1] - r.pos[1]) * (step / d)};
    return mv;
  }
  const ex::RobotParams params{};
  const ex::BodyState pose{r.pos[0], r.pos[1], r.theta_rad};
  const ex::ControllerInputs in{pose, r.waypoint, r.on_leg ? 0 : 1, w.o.dt_s};  // 1: a waypoint to take
  mv.controller = ex::controller_step(params, r.controller, in);
  const ex::BodyState next = ex::body_step(params, pose, mv.controller.servo_left,
                                           mv.controller.servo_right, w.o.dt_s);
  mv.pos = {next.x_m, next.y_m};
  mv.theta_rad = next.theta_rad;
  if (!r.on_leg && mv.controller.on_destination_output == 0) mv.on_leg = true;
  if (r.on_leg && mv.controller.on_destination_output == 1) mv.arrived = true;
  return mv;
}

void report(World& w, const sm::IntervalRecord& rec) {
  if (w.observer) w.observer->on_interval(rec);
  w.result.intervals.push_back(rec);
}

// Rule 3's activity: each robot's interval grows over (t_from, t_to] or closes and a new opens.
void account(World& w, const std::vector<sm::Activity>& did, double t_from, double t_to) {
  for (std::size_t i = 0; i < w.robots.size(); ++i) {
    Robot& r = w.robots[i];
    if (r.open && r.open->activity == did[i]) {
      r.open->to_s = t_to;
      continue;
    }
    if (r.open) report(w, *r.open);
    r.open = sm::IntervalRecord{w.m.robots[i].name, did[i], t_from, t_to};
  }
}

// Cells new on robot i's map (spec/mission/sensing.hpp) re-route it from where it is; false
// when none was new.
bool learn(World& w, std::size_t i, const std::vector<std::size_t>& cells) {
  Robot& r = w.robots[i];
  if (!sm::add_to_map(r.map, cells)) return false;
  r.trav = sm::traversable_on(*w.m.world, r.map, w.m.robots[i].radius);
  ++w.result.replans_sensed;
  r.on_leg = false;
  r.following = false;
  r.route.clear();
  return true;
}

// Local steering (spec/mission/steering.hpp): robot i, in a standoff, tries the detour points
// in order; the first whose move passes the world and the yield test is its move.
struct Steered {
  sm::Point detour;
  Move move;
};

std::optional<Steered> steer(const World& w, std::size_t i) {
  const Robot& r = w.robots[i];
  const std::vector<sm::Point> at = positions(w);
  sm::SteerView view{at};
  if (w.m.world) {
    view.map = w.sensing ? &r.map : &w.m.world->occupied;
    view.traversable = w.sensing ? &r.trav : &w.m.world->traversable[i];
  }
  for (const sm::Point& e : sm::steer_candidates(w.m, i, r.pos, r.waypoint, view)) {
    Robot fresh = r;  // a new leg to e
    fresh.waypoint = e;
    fresh.on_leg = false;
    const Move mv = propose(w, fresh);
    const double radius = w.m.robots[i].radius;
    if (w.m.world && sm::overlaps_obstacle(w.sensing ? w.truth : *w.m.world, mv.pos, radius)) continue;
    if (sm::yields_to(w.m, i, r.pos, mv.pos, ways(w))) continue;
    return Steered{e, mv};
  }
  return std::nullopt;
}

// Rule 3 for every robot; false when no robot moved.
bool move_all(World& w, double t_from, double t, std::uint64_t step) {
  bool moved = false;
  using Wait = std::optional<std::pair<std::size_t, bool>>;  // whom it yielded to, and stuck
  const auto wait_of = [](const Robot& r) { return r.yielded ? Wait({r.yielded_to, r.stuck}) : Wait(); };
  std::vector<Wait> waited;
  for (const Robot& r : w.robots) waited.push_back(wait_of(r));
  std::vector<sm::Activity> did(w.robots.size(), sm::Activity::waiting_for_task);
  for (std::size_t i = 0; i < w.robots.size(); ++i) {
    Robot& r = w.robots[i];
    r.blocked = false;
    r.yielded = false;
    r.stuck = false;
    if (r.tasks.empty()) continue;
    if (w.sensing) learn(w, i, sm::scan_cells(w.truth, r.pos, w.o.seed, step, i));
    if (!r.on_leg && !r.following) start_leg(w, i);
    Move mv = propose(w, r);
    if (w.sensing && sm::overlaps_obstacle(w.truth, mv.pos, w.m.robots[i].radius)) {  // a bump
      ++w.result.bumps;
      did[i] = sm::Activity::busy;
      moved = learn(w, i, sm::overlapped_cells(w.truth, mv.pos, w.m.robots[i].radius)) || moved;
      continue;
    }
    if (w.m.world && sm::overlaps_obstacle(*w.m.world, mv.pos, w.m.robots[i].radius))
      throw std::logic_error(fmt::format("robot {} would overlap an obstacle at [{}, {}] at t = {} s",
                                         w.m.robots[i].name, mv.pos[0], mv.pos[1], t));
    std::optional<Steered> steered;
    if (const auto j = sm::yields_to(w.m, i, r.pos, mv.pos, ways(w))) {
      const bool cornered = sm::standoff(i, *j, ways(w));
      if (cornered) steered = steer(w, i);
      if (!steered) {
        r.yielded = true;
        r.yielded_to = *j;
        r.stuck = cornered;
        ++w.result.yields;
        did[i] = sm::Activity::waiting_for_robot;
        continue;
      }
      mv = steered->move;
    }
    const std::vector<std::string> entries = sm::entry_events(w.m, i, r.pos, mv.pos);
    if (!sm::fire_all(w.m, w.q, entries)) {
      r.blocked = true;
      did[i] = sm::Activity::waiting_for_supervisor;
      continue;
    }
    did[i] = sm::Activity::busy;
    moved = true;
    if (steered) {  // the detour is the robot's leg now
      ++w.result.steers;
      r.waypoint = steered->detour;
      r.waypoint_is_task = false;
      r.route.clear();
      r.following = false;
    }
    r.travelled_m += sm::distance(r.pos, mv.pos);
    r.pos = mv.pos;
    r.theta_rad = mv.theta_rad;
    r.controller = mv.controller;
    r.on_leg = mv.on_leg;
    if (mv.arrived) {
      r.on_leg = false;
      r.following = !r.route.empty();
      if (r.following) {  // on to the route's next waypoint
        r.waypoint = r.route.front();
        r.route.erase(r.route.begin());
      } else if (r.waypoint_is_task) {
        r.tasks.erase(r.tasks.begin());
      }
    }
    for (const auto& e : entries) fire(w, e, t);
  }
  account(w, did, t_from, t);
  for (std::size_t i = 0; i < w.robots.size(); ++i) {  // new yields are progress too
    const Robot& r = w.robots[i];
    if (waited[i] != wait_of(r)) moved = true;
  }
  return moved;
}

std::string deadlock_reason(const World& w) {
  std::string enabled;
  for (const auto& e : swarmcheck::supervisor::enabled(w.m.fsm, w.q))
    enabled += (enabled.empty() ? "" : ", ") + e;
  std::string out = fmt::format("deadlock in state {}: no robot can move (enabled events: {})",
                                w.q, enabled.empty() ? "none" : enabled);
  for (std::size_t i = 0; i < w.robots.size(); ++i) {
    if (!w.robots[i].blocked) continue;
    const Move mv = propose(w, w.robots[i]);
    for (const auto& e : sm::entry_events(w.m, i, w.robots[i].pos, mv.pos))
      if (!swarmcheck::supervisor::successor(w.m.fsm, w.q, e))
        out += fmt::format("; robot {} waits to fire {}", w.m.robots[i].name, e);
  }
  for (std::size_t i = 0; i < w.robots.size(); ++i) {
    if (!w.robots[i].yielded) continue;
    out += fmt::format("; robot {} yields to robot {}", w.m.robots[i].name,
                       w.m.robots[w.robots[i].yielded_to].name);
  }
  return out;
}

}  // namespace

sm::RunResult run_model(const sm::Mission& m, const sm::RunOptions& o, const PlanFunction& plan,
                        sm::RunObserver* observer) {
  SWARM_DEMAND(o.dt_s > 0);
  World w{m, o, plan, observer, m.initial_state, {}, {}, {}, {}, false, false, false, {}};
  w.robots.resize(m.robots.size());
  for (std::size_t i = 0; i < m.robots.size(); ++i) w.robots[i].pos = m.robots[i].start;
  w.sensing = m.world && !m.world->hidden.empty();
  if (w.sensing) {
    w.truth = sm::true_world(*m.world);
    for (std::size_t i = 0; i < m.robots.size(); ++i) {
      w.robots[i].map = m.world->occupied;
      w.robots[i].trav = m.world->traversable[i];
    }
  }
  for (const auto& e : sm::initial_entries(m)) fire(w, e, 0.0);
  const sm::Plan first = ask(w);
  w.result.makespan_planned = first.found ? first.cost.makespan : 0.0;
  if (first.found) w.current = first.events;
  w.result.clearance_min_m = sm::kNoClearance;
  check_apart(w, 0.0);
  record_step(w, 0.0);
  double t = 0.0;
  const auto steps_max = static_cast<long long>(o.max_time_s / o.dt_s);
  for (long long k = 0;; ++k) {
    if (!choose(w, t)) break;
    if (sm::is_marked(m, w.q)) {
      w.result.completed = true;
      w.result.reason = "mission complete";
      break;
    }
    if (k >= steps_max) {
      w.result.reason = fmt::format("time limit of {} s reached", o.max_time_s);
      break;
    }
    const double t_from = t;
    t = static_cast<double>(k + 1) * o.dt_s;
    const bool moved = move_all(w, t_from, t, static_cast<std::uint64_t>(k));
    check_apart(w, t);
    if (!moved) {
      w.result.reason = deadlock_reason(w);
      break;
    }
    record_step(w, t);
  }
  w.result.final_state = w.q;
  w.result.time_s = t;
  for (const Robot& r : w.robots) w.result.travel.push_back(r.travelled_m);
  for (const Robot& r : w.robots)
    if (r.open) report(w, *r.open);
  return w.result;
}

}  // namespace swarmcheck::model::mission
