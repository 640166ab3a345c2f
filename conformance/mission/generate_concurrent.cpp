// Generated missions for the properties of concurrent execution, and the robot-by-robot
// execution of a plan they are compared against.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "conformance/mission/generate.hpp"

namespace swarmcheck::conformance::mission {

namespace {

namespace sm = swarmcheck::mission;
namespace sv = swarmcheck::supervisor;

// The segment a-b meets the closed rectangle g grown by 0.01 m (Liang-Barsky clipping).
bool segment_meets(const sm::Point& a, const sm::Point& b, const sm::Region& g) {
  double lo = 0.0, hi = 1.0;
  for (std::size_t k = 0; k < 2; ++k) {
    const double d = b[k] - a[k];
    const double g_lo = g.lo[k] - 0.01, g_hi = g.hi[k] + 0.01;
    if (d == 0.0) {
      if (a[k] < g_lo || a[k] > g_hi) return false;
      continue;
    }
    double t0 = (g_lo - a[k]) / d, t1 = (g_hi - a[k]) / d;
    if (t0 > t1) std::swap(t0, t1);
    lo = std::max(lo, t0);
    hi = std::min(hi, t1);
  }
  return lo <= hi;
}

// No leg a robot may drive (start to task, task to task) meets the square of a third task.
bool legs_clear(const sm::Mission& m) {
  std::vector<sm::Point> from;
  for (const auto& r : m.robots) from.push_back(r.start);
  for (const auto& t : m.tasks) from.push_back(t.at);
  for (std::size_t i = 0; i < from.size(); ++i)
    for (std::size_t t = 0; t < m.tasks.size(); ++t)
      for (std::size_t g = 0; g < m.regions.size(); ++g) {
        const bool own = g == t || (i >= m.robots.size() && i - m.robots.size() == g);
        if (!own && segment_meets(from[i], m.tasks[t].at, m.regions[g])) return false;
      }
  return true;
}

template <class T>
rc::Gen<T> uniform_in(T lo, T hi) {
  return rc::gen::resize(100, rc::gen::inRange<T>(lo, hi));
}

}  // namespace

rc::Gen<RunCase> concurrent_case() {
  const auto mission = rc::gen::exec([] {
    const auto robots = *uniform_in<std::size_t>(1, 4);
    const auto tasks = *uniform_in<std::size_t>(1, 5);
    const auto capacity = *uniform_in<std::size_t>(1, robots + 1);
    const auto per_robot = *uniform_in<std::size_t>(1, 3);
    // Symmetric: tasks on the axes at distance 10, robots at the centre or on the diagonals, so
    // that several assignments cost exactly the same.
    const bool symmetric = *uniform_in(0, 2) == 0;
    std::vector<sm::Point> starts, points;
    for (std::size_t r = 0; r < robots; ++r)
      starts.push_back(symmetric ? sm::Point{double(*rc::gen::element(-2, 0, 2)), double(*rc::gen::element(-2, 0, 2))}
                                 : sm::Point{double(*uniform_in(-3, 4)), double(*uniform_in(-3, 4))});
    for (std::size_t t = 0; t < tasks; ++t) {
      const double angle = 2 * std::numbers::pi * (double(t) + *uniform_in(-30, 31) / 100.0) / double(tasks);
      const double radius = *uniform_in(8, 13);
      points.push_back(symmetric ? std::vector<sm::Point>{{10, 0}, {0, 10}, {-10, 0}, {0, -10}}[t]
                                 : sm::Point{std::round(radius * std::cos(angle)), std::round(radius * std::sin(angle))});
    }
    return allocation_mission_at(starts, points, capacity, per_robot);
  });
  return rc::gen::apply(
      [](const sm::Mission& m, double dt, double speed) {
        sm::RunOptions o;
        o.body = sm::BodyModel::kinematic;
        o.dt_s = dt;
        o.speed_m_per_s = speed;
        o.max_time_s = 3600.0;
        return RunCase{m, o};
      },
      rc::gen::suchThat(mission, legs_clear), rc::gen::element(0.05, 0.1, 0.2),
      rc::gen::element(0.5, 1.0, 2.0));
}

sm::Mission robot_by_robot(const sm::Mission& m, const std::vector<std::string>& plan) {
  std::vector<std::string> order = plan;
  std::stable_sort(order.begin(), order.end(), [&](const std::string& a, const std::string& b) {
    return m.events.at(a).robot < m.events.at(b).robot;
  });
  sm::Mission out = m;
  out.fsm = sv::Automaton{};
  out.fsm.events = m.fsm.events;
  for (std::size_t q = 0; q <= order.size(); ++q) out.fsm.states.push_back("p" + std::to_string(q));
  for (std::size_t q = 0; q < order.size(); ++q)
    out.fsm.delta[out.fsm.states[q]][order[q]] = out.fsm.states[q + 1];
  out.fsm.marked.insert(out.fsm.states.back());
  out.initial_state = out.fsm.states.front();
  out.marked_states = {out.fsm.states.back()};
  return out;
}

}  // namespace swarmcheck::conformance::mission
