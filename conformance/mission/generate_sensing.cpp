// Generated run cases with unknown obstacles and the range sensor (generate.hpp, sensing_case):
// robots that scan, learn cells, re-route and bump.
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <map>
#include <string>
#include <vector>

#include "conformance/mission/counterexample.hpp"
#include "conformance/mission/generate.hpp"
#include "spec/util/input_error.hpp"

namespace swarmcheck::conformance::mission {

namespace {

namespace sm = swarmcheck::mission;

// A wall `thickness` thick and 2 `half_length` long, across the way from `from` to `to` at the
// fraction `at` of it (a rectangle turned to face the way).
sm::ObstacleDecl wall_across(const sm::Point& from, const sm::Point& to, double at, double half_length,
                             double thickness) {
  const double dx = to[0] - from[0], dy = to[1] - from[1];
  const double length = std::sqrt(dx * dx + dy * dy);
  const double ux = dx / length, uy = dy / length;   // along the way
  const double px = -uy, py = ux;                    // across it
  const sm::Point m{from[0] + at * dx, from[1] + at * dy};
  const double h = thickness / 2;
  return sm::ObstacleDecl{{{m[0] - half_length * px - h * ux, m[1] - half_length * py - h * uy},
                           {m[0] + half_length * px - h * ux, m[1] + half_length * py - h * uy},
                           {m[0] + half_length * px + h * ux, m[1] + half_length * py + h * uy},
                           {m[0] - half_length * px + h * ux, m[1] - half_length * py + h * uy}}};
}

// The ways robots drive on the FSM's path to its marked state (generate_run.cpp: states q0, q1,
// ... along it, task starts "<robot>s<task>"): each robot from its start to its first task, and
// on from task to task.
std::vector<std::pair<sm::Point, sm::Point>> spine_ways(const RunDecl& r) {
  const sm::MissionDecl& d = r.decl;
  std::map<char, sm::Point> at;
  for (const auto& robot : d.robots) at[robot.name[0]] = robot.start;
  std::vector<std::pair<sm::Point, sm::Point>> ways;
  for (std::size_t q = 0;; ++q) {
    const auto row = r.fsm.delta.find("q" + std::to_string(q));
    if (row == r.fsm.delta.end()) break;
    const std::string next = "q" + std::to_string(q + 1);
    const auto edge = std::find_if(row->second.begin(), row->second.end(), [&](const auto& e) { return e.second == next; });
    if (edge == row->second.end()) break;
    const std::string& e = edge->first;
    if (e.size() < 3 || e[1] != 's') continue;   // a region entry
    const sm::Point task = d.tasks[std::stoul(e.substr(2))].at;
    ways.emplace_back(at[e[0]], task);
    at[e[0]] = task;
  }
  return ways;
}

// Uniform whatever RapidCheck's size (which would make the first cases all take the first
// value); shrinking still goes towards the first.
template <class T>
T any_of(std::initializer_list<T> values) {
  return *rc::gen::resize(100, rc::gen::elementOf(std::vector<T>(values)));
}

// A task allocation (generate.hpp, allocation_mission_at): 1..3 robots, 1..3 tasks on integer
// points of [-7, 7]^2, each task in its 2 m square region, starts moved out of the squares; every
// robot drives to the tasks it is given.
RunDecl allocation_decl() {
  const auto point = [] {
    return sm::Point{static_cast<double>(*rc::gen::resize(100, rc::gen::inRange(-7, 8))),
                     static_cast<double>(*rc::gen::resize(100, rc::gen::inRange(-7, 8)))};
  };
  std::vector<sm::Point> starts, tasks;
  const int robots = any_of({1, 2, 3}), count = any_of({1, 2, 3});
  for (int t = 0; t < count; ++t) tasks.push_back(point());
  for (int r = 0; r < robots; ++r) {
    sm::Point p = point();
    for (int pass = 0; pass < 8; ++pass)
      for (const auto& t : tasks)
        if (std::abs(p[0] - t[0]) <= 1.0 && std::abs(p[1] - t[1]) <= 1.0) p[1] = p[1] > -8.0 ? p[1] - 1.0 : 9.0;
    starts.push_back(p);
  }
  const sm::Mission m = allocation_mission_at(starts, tasks, static_cast<std::size_t>(robots));
  RunDecl r;
  r.decl = sm::parse_mission_text(mission_json(m, "generated.fsm", "generated"), "generated");
  r.fsm = m.fsm;
  return r;
}

bool passes_check(const sm::MissionDecl& d, const swarmcheck::supervisor::Automaton& fsm) {
  try {
    (void)sm::check_mission(d, fsm, "generated");
    return true;
  } catch (const InputError&) {
    return false;
  }
}

}  // namespace

rc::Gen<RunCase> sensing_case() {
  return rc::gen::exec([] {
    // Half the cases a task allocation (robots drive to every task), half run_case's missions
    // (regions to enter on the way, supervisors that may block).
    const bool allocation = any_of({true, false});
    RunDecl r = allocation ? allocation_decl() : *run_decl();
    sm::MissionDecl& d = r.decl;
    sm::WorldDecl w;
    w.resolution_m = any_of({0.5, 0.25});
    w.origin = {-10, -10};
    w.size_m = sm::Point{20, 20};
    // From nearly blind (one beam, a quarter metre: the robots find walls by bumping into them)
    // to a sensor that sees them in time.
    const bool blind = any_of({true, false});
    const auto beams = blind ? std::size_t{1} : any_of<std::size_t>({3, 8, 24});
    const double range = blind ? 0.25 : any_of({1.0, 3.0});
    w.sensor = sm::SensorDecl{beams, range, any_of({0.0, 0.0, 0.05})};
    w.unknown_obstacles = std::vector<sm::ObstacleDecl>{};
    d.world = w;
    for (std::size_t i = 0; i < d.robots.size(); ++i) d.radii.push_back(any_of({0.0, 0.2, 0.3}));
    // Robots that start too close for their radii (run_decl's starts may even coincide) are points.
    for (std::size_t i = 0; i < d.robots.size(); ++i)
      for (std::size_t j = i + 1; j < d.robots.size(); ++j) {
        const double dx = d.robots[i].start[0] - d.robots[j].start[0], dy = d.robots[i].start[1] - d.robots[j].start[1];
        if (std::sqrt(dx * dx + dy * dy) < d.radii[i] + d.radii[j]) d.radii[i] = d.radii[j] = 0.0;
      }
    // Walls across the ways the robots drive (and now and then across another start-to-task way),
    // each kept only if the mission still passes.
    std::vector<std::pair<sm::Point, sm::Point>> ways = allocation ? std::vector<std::pair<sm::Point, sm::Point>>{}
                                                                   : spine_ways(r);
    const auto others = allocation ? any_of({1, 2, 3}) : any_of({0, 1});
    for (int k = 0; k < others; ++k)
      ways.emplace_back(d.robots[*rc::gen::resize(100, rc::gen::inRange<std::size_t>(0, d.robots.size()))].start,
                        d.tasks[*rc::gen::resize(100, rc::gen::inRange<std::size_t>(0, d.tasks.size()))].at);
    for (std::size_t k = 0; k < ways.size() && k < 4; ++k) {
      const auto& [from, to] = ways[k];
      const double dx = to[0] - from[0], dy = to[1] - from[1];
      if (dx * dx + dy * dy < 2.0) continue;
      const sm::ObstacleDecl wall = wall_across(from, to, any_of({0.5, 0.35, 0.65}),
                                                any_of({1.0, 0.5, 2.0}), any_of({0.5, 1.0}));
      const bool known = any_of({0, 1, 2, 3, 4}) == 4;   // mostly unknown
      auto& list = known ? d.world->obstacles : d.world->unknown_obstacles;
      if (!list) list = std::vector<sm::ObstacleDecl>{};
      list->push_back(wall);
      if (!passes_check(d, r.fsm)) list->pop_back();
    }
    RunCase c{sm::check_mission(d, r.fsm, "generated"), draw_run_options()};
    c.options.seed = any_of<std::uint64_t>({1, 2, 99});
    // Long enough for the robots to reach the walls.
    c.options.max_time_s = any_of({400.0, 1200.0}) * c.options.dt_s;
    return c;
  });
}

}  // namespace swarmcheck::conformance::mission
