// Generated run cases: valid missions (checked by check_mission) with small supervisors, and run
// options, for the differential runner.
#include <algorithm>
#include <initializer_list>
#include <string>
#include <vector>

#include "conformance/mission/generate.hpp"

namespace swarmcheck::conformance::mission {

namespace {

namespace sm = swarmcheck::mission;
namespace sv = swarmcheck::supervisor;

// Uniform in [lo, hi) whatever RapidCheck's size (which would otherwise make the first cases all
// minimal); shrinking still goes towards lo.
template <class T>
rc::Gen<T> uniform(T lo, T hi) {
  return rc::gen::resize(100, rc::gen::inRange<T>(lo, hi));
}

template <class T>
T one_of(std::initializer_list<T> values) {
  const std::vector<T> v(values);
  return v[*uniform<std::size_t>(0, v.size())];
}

rc::Gen<sm::Point> integer_point(int lo, int hi) {
  auto coord = rc::gen::map(uniform(lo, hi + 1), [](int v) { return double(v); });
  return rc::gen::apply([](double x, double y) { return sm::Point{x, y}; }, coord, coord);
}

bool inside(const sm::RegionDecl& g, const sm::Point& p) {
  const auto& [a, b] = g.corners;
  return std::min(a[0], b[0]) < p[0] && p[0] < std::max(a[0], b[0]) &&
         std::min(a[1], b[1]) < p[1] && p[1] < std::max(a[1], b[1]);
}

// Regions: around some tasks a square (so a robot doing the task enters it), and up to two
// rectangles anywhere in [-6, 6]^2 (which robots may cross on the way, or be sent through).
void add_regions(sm::MissionDecl& d) {
  auto add = [&](sm::Point lo, double w, double h) {
    const std::string name = "g" + std::to_string(d.regions.size());
    d.regions.push_back(sm::RegionDecl{name, {lo, sm::Point{lo[0] + w, lo[1] + h}}});
  };
  for (const auto& t : d.tasks) {
    if (*uniform(0, 3) == 0) continue;
    const auto half = double(*uniform(1, 3));
    add({t.at[0] - half, t.at[1] - half}, 2 * half, 2 * half);
  }
  const auto free = *uniform<std::size_t>(0, 3);
  for (std::size_t k = 0; k < free; ++k)
    add(*integer_point(-6, 5), double(*uniform(1, 7)), double(*uniform(1, 7)));
}

// Robots "a", "b", "c": each starts on a random point, or just below the map when that point is
// inside a region (no entry fires at time 0, so no initial entry can be disabled).
void add_robots(sm::MissionDecl& d, std::size_t robots) {
  for (std::size_t r = 0; r < robots; ++r) {
    sm::Point start = *integer_point(-6, 6);
    for (const auto& g : d.regions)
      if (inside(g, start)) start[1] = -9;
    d.robots.push_back(sm::RobotDecl{std::string(1, char('a' + r)), start});
  }
}

// Every meaning gets an event; returns the events with their controllability.
std::vector<std::pair<std::string, bool>> add_meanings(sm::MissionDecl& d) {
  std::vector<std::pair<std::string, bool>> events;
  for (const auto& r : d.robots) {
    for (std::size_t t = 0; t < d.tasks.size(); ++t) {
      const std::string e = r.name + "s" + std::to_string(t);
      d.events[e] = sm::MeaningDecl{r.name, d.tasks[t].name, std::nullopt};
      events.emplace_back(e, true);
    }
    for (std::size_t g = 0; g < d.regions.size(); ++g) {
      const std::string e = r.name + "e" + std::to_string(g);
      d.events[e] = sm::MeaningDecl{r.name, std::nullopt, d.regions[g].name};
      events.emplace_back(e, false);
    }
  }
  return events;
}

// The events of a mission's path to the marked state: 1..4 times a robot starts a task and
// then (mostly) enters a region, the task's own when there is one, else any.
std::vector<std::string> spine(const sm::MissionDecl& d) {
  std::vector<std::string> events;
  const auto tasks_done = *uniform<std::size_t>(1, 5);
  for (std::size_t k = 0; k < tasks_done; ++k) {
    const std::string& robot = d.robots[*uniform<std::size_t>(0, d.robots.size())].name;
    const auto t = *uniform<std::size_t>(0, d.tasks.size());
    events.push_back(robot + "s" + std::to_string(t));
    if (d.regions.empty() || *uniform(0, 4) == 0) continue;
    std::size_t g = *uniform<std::size_t>(0, d.regions.size());
    for (std::size_t h = 0; h < d.regions.size(); ++h)
      if (inside(d.regions[h], d.tasks[t].at) && *uniform(0, 4) != 0) g = h;
    events.push_back(robot + "e" + std::to_string(g));
  }
  return events;
}

// States q0..: the spine from q0 to a marked state, 0..3 more states, and random edges (an edge
// never replaces one already there, so the spine stays).
sv::Automaton fsm_over(const std::vector<std::pair<std::string, bool>>& events,
                       const std::vector<std::string>& path) {
  sv::Automaton a;
  const std::size_t n = path.size() + 1 + *uniform<std::size_t>(0, 4);
  for (std::size_t q = 0; q < n; ++q) a.states.push_back("q" + std::to_string(q));
  auto edge = [&](std::size_t from, std::size_t to, const std::pair<std::string, bool>& e) {
    if (a.delta[a.states[from]].emplace(e.first, a.states[to]).second)
      a.events[e.first] = sv::EventAttr{e.second, true};
  };
  for (std::size_t q = 0; q < path.size(); ++q)
    edge(q, q + 1, *std::find_if(events.begin(), events.end(),
                                 [&](const auto& e) { return e.first == path[q]; }));
  a.marked.insert(a.states[path.size()]);
  const auto extra = *uniform<std::size_t>(0, 2 * n);
  for (std::size_t k = 0; k < extra; ++k)
    edge(*uniform<std::size_t>(0, n), *uniform<std::size_t>(0, n),
         events[*uniform<std::size_t>(0, events.size())]);
  return a;
}

}  // namespace

sm::RunOptions draw_run_options() {
  sm::RunOptions o;
  o.body = one_of({sm::BodyModel::kinematic, sm::BodyModel::unicycle});
  o.dt_s = one_of({0.05, 0.1, 0.2, 0.5});
  o.speed_m_per_s = one_of({0.25, 0.5, 1.0, 2.0});
  const double steps = one_of({10.0, 100.0, 400.0, 1200.0});
  o.max_time_s = steps * o.dt_s;
  return o;
}

rc::Gen<RunDecl> run_decl() {
  return rc::gen::exec([] {
    RunDecl r;
    sm::MissionDecl& d = r.decl;
    d.fsm = "generated.fsm";
    const auto tasks = *uniform<std::size_t>(1, 4);
    for (std::size_t t = 0; t < tasks; ++t)
      d.tasks.push_back(sm::TaskDecl{"t" + std::to_string(t), *integer_point(-5, 5)});
    add_regions(d);
    add_robots(d, *uniform<std::size_t>(1, 4));
    r.fsm = fsm_over(add_meanings(d), spine(d));
    d.initial_state = r.fsm.states.front();
    d.marked_states.assign(r.fsm.marked.begin(), r.fsm.marked.end());
    return r;
  });
}

rc::Gen<RunCase> run_case() {
  return rc::gen::exec([] {
    const RunDecl r = *run_decl();
    return RunCase{sm::check_mission(r.decl, r.fsm, "generated"), draw_run_options()};
  });
}

}  // namespace swarmcheck::conformance::mission
