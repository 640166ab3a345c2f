// Missions in cluttered worlds (issue 14): generated task-allocation missions
// (conformance::mission::allocation_mission_at) for 3..8 robots and 3..4 tasks in a 24 m x 24 m
// world of 0.25 m cells with 14 random polygon obstacles (triangles and thin slanted walls,
// seeded), robots of radius 0.2 m. Starts and tasks are drawn (seeded) until check_world,
// check_robots_apart and a plan accept the mission; the mission is built once per size.
// BM_ClutteredPlan: the exact planner from the initial query (a fresh Planner each time).
// BM_ClutteredRun: run_mission with the kinematic body (0.5 m/s, dt 0.1 s).
// Counters: states; makespan_planned_m (the plan's, metres of route); makespan_realised_m (the
// largest distance a robot drove); realised_over_planned; run time_s; yields (robot-steps a
// robot waited for another).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>

#include "conformance/mission/generate.hpp"
#include "impl/mission/planner.hpp"
#include "spec/mission/separation.hpp"
#include "spec/mission/world.hpp"
#include "spec/util/input_error.hpp"
#include "swarmcheck/mission.hpp"

namespace {

namespace sm = swarmcheck::mission;

constexpr double kSide_m = 24.0;

std::vector<sm::ObstacleDecl> clutter(std::mt19937_64& g) {
  std::uniform_real_distribution<double> at(1.0, kSide_m - 1.0), d(-1.5, 1.5);
  std::vector<sm::ObstacleDecl> out;
  for (int k = 0; k < 14; ++k) {
    const sm::Point c{at(g), at(g)};
    if (k % 2 == 0) {  // a triangle
      out.push_back({{{c[0] + d(g), c[1] + d(g)}, {c[0] + d(g), c[1] + d(g)}, {c[0] + d(g), c[1] + d(g)}}});
    } else {  // a thin slanted wall 0.1 m thick
      const double a = d(g), b = d(g), n = std::max(1e-3, std::hypot(a, b));
      const double ox = -b / n * 0.1, oy = a / n * 0.1;
      out.push_back({{{c[0] - a, c[1] - b}, {c[0] + a, c[1] + b}, {c[0] + a + ox, c[1] + b + oy},
                      {c[0] - a + ox, c[1] - b + oy}}});
    }
  }
  return out;
}

// A valid cluttered mission for `robots` robots, the first seed from 1 that gives one.
sm::Mission cluttered(std::size_t robots) {
  const std::size_t tasks = robots == 3 ? 3 : 4;
  for (std::uint64_t seed = 1;; ++seed) {
    std::mt19937_64 g(seed * 1000 + robots);
    std::uniform_real_distribution<double> at(1.0, kSide_m - 1.0);
    std::vector<sm::Point> starts, points;
    for (std::size_t r = 0; r < robots; ++r) starts.push_back({at(g), at(g)});
    for (std::size_t t = 0; t < tasks; ++t) points.push_back({at(g), at(g)});
    sm::Mission m = swarmcheck::conformance::mission::allocation_mission_at(starts, points);
    sm::WorldDecl d;
    d.resolution_m = 0.25;
    d.origin = {0, 0};
    d.size_m = sm::Point{kSide_m, kSide_m};
    d.obstacles = clutter(g);
    m.world = sm::build_world(d);
    for (auto& r : m.robots) {
      r.radius = 0.2;
      m.world->traversable.push_back(sm::traversable_cells(*m.world, r.radius));
    }
    bool starts_outside = true;
    for (const auto& r : m.robots)
      for (const auto& reg : m.regions) starts_outside = starts_outside && !sm::inside(reg, r.start);
    if (!starts_outside) continue;
    try {
      sm::check_world(m);
      sm::check_robots_apart(m);
    } catch (const swarmcheck::InputError&) {
      continue;
    }
    if (sm::Planner(m).plan(sm::initial_query(m)).found) return m;
  }
}

const sm::Mission& mission_for(std::size_t robots) {
  static std::map<std::size_t, sm::Mission> cache;
  auto it = cache.find(robots);
  if (it == cache.end()) it = cache.emplace(robots, cluttered(robots)).first;
  return it->second;
}

void BM_ClutteredPlan(benchmark::State& st) {
  const sm::Mission& m = mission_for(static_cast<std::size_t>(st.range(0)));
  const auto q = sm::initial_query(m);
  double makespan = NAN;
  for (auto _ : st) {
    swarmcheck::impl::mission::Planner p(m);
    const sm::Plan plan = p.plan(q);
    makespan = plan.found ? plan.cost.makespan : NAN;
    benchmark::DoNotOptimize(plan);
  }
  st.counters["states"] = double(m.fsm.states.size());
  st.counters["makespan_planned_m"] = makespan;
}
BENCHMARK(BM_ClutteredPlan)->DenseRange(3, 8)->ArgName("robots")->Unit(benchmark::kMillisecond);

void BM_ClutteredRun(benchmark::State& st) {
  const sm::Mission& m = mission_for(static_cast<std::size_t>(st.range(0)));
  sm::RunOptions o;
  o.body = sm::BodyModel::kinematic;
  o.dt_s = 0.1;
  sm::RunResult r;
  for (auto _ : st) {
    r = sm::run_mission(m, o);
    benchmark::DoNotOptimize(r);
  }
  const double realised = r.travel.empty() ? NAN : *std::max_element(r.travel.begin(), r.travel.end());
  st.counters["completed"] = r.completed ? 1 : 0;
  st.counters["makespan_planned_m"] = r.makespan_planned;
  st.counters["makespan_realised_m"] = realised;
  st.counters["realised_over_planned"] = realised / r.makespan_planned;
  st.counters["time_s"] = r.time_s;
  st.counters["yields"] = double(r.yields);
}
BENCHMARK(BM_ClutteredRun)->DenseRange(3, 8)->ArgName("robots")->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
