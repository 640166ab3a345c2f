// Planning time: the exact planner (impl, a fresh Planner each time: no cache, so the FSM's
// compilation and reachability are inside the time) against the thesis's modified Dijkstra
// (model), on the thesis mission and on generated task-allocation missions
// (conformance::mission::allocation_mission, seed 7) with 2..6 robots: a state records each
// task as free, in progress by one robot, or done; a robot starts a free task (controllable)
// and finishes it by entering the task's region (uncontrollable); marked: all tasks done.
// With r robots and t tasks the FSM has sum_k C(t, k) r!/(r-k)! 2^(t-k) states.
//
// BM_Allocation: small FSMs (4 tasks: 128 .. 2 248 states) where the baseline finishes; it is
//   timed once per mission (cached across Google Benchmark's calibration rounds) and reported
//   as baseline_ms and ratio = baseline / exact. Its Calculate Costs is cubic in the states
//   (13 s at 2 248 states), so it is not run above kBaselineStatesMax.
// BM_AllocationLarge: FSMs of ~10^4 .. ~2 x 10^5 states (2 robots 9 tasks .. 6 robots 6 tasks),
//   the exact planner alone (baseline_ms and ratio NaN, "-" in the docs). The mission itself
//   (string-keyed FSM of up to 2 x 10^5 states) is generated once per size, outside the time.
// Counters: states, labels (labels the exact search created), makespan.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <map>

#include "conformance/mission/generate.hpp"
#include "swarmcheck/mission.hpp"
#include "impl/mission/planner.hpp"
#include "model/mission/thesis_dijkstra.hpp"

namespace {

namespace sm = swarmcheck::mission;

constexpr std::size_t kBaselineStatesMax = 2'500;

double seconds_of(const std::function<void()>& f, int reps) {
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < reps; ++i) f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / reps;
}

// The baseline's time for one mission, measured on first use only.
double baseline_once(const std::string& key, const sm::Mission& m, const sm::PlanQuery& q) {
  static std::map<std::string, double> cache;
  const auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  return cache[key] = seconds_of(
             [&] { benchmark::DoNotOptimize(swarmcheck::model::mission::thesis_plan(m, q)); }, 1);
}

void run(benchmark::State& st, const std::string& key, const sm::Mission& m) {
  const auto q = sm::initial_query(m);
  double exact_s = 0;
  std::size_t labels = 0;
  double makespan = NAN;
  for (auto _ : st) {
    const auto t0 = std::chrono::steady_clock::now();
    swarmcheck::impl::mission::Planner p(m);
    const sm::Plan plan = p.plan(q);
    exact_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    labels = p.labels_last();
    makespan = plan.found ? plan.cost.makespan : NAN;
    benchmark::DoNotOptimize(plan);
  }
  const double exact = st.iterations() ? exact_s / double(st.iterations()) : NAN;
  const double base = m.fsm.states.size() <= kBaselineStatesMax ? baseline_once(key, m, q) : NAN;
  st.counters["states"] = double(m.fsm.states.size());
  st.counters["labels"] = double(labels);
  st.counters["makespan"] = makespan;
  st.counters["baseline_ms"] = base * 1e3;
  st.counters["ratio"] = base / exact;
}

// The mission for (robots, tasks), generated once per size.
const sm::Mission& allocation(std::size_t robots, std::size_t tasks) {
  static std::map<std::pair<std::size_t, std::size_t>, sm::Mission> cache;
  const auto k = std::make_pair(robots, tasks);
  auto it = cache.find(k);
  if (it == cache.end())
    it = cache.emplace(k, swarmcheck::conformance::mission::allocation_mission(robots, tasks, 7))
             .first;
  return it->second;
}

std::string key_of(const benchmark::State& st) {
  return std::to_string(st.range(0)) + "/" + std::to_string(st.range(1));
}

// The thesis's own mission: 2 robots, 4 tasks, the 72-state supervisor control2.fsm.
void BM_Thesis(benchmark::State& st) {
  static const auto m =
      swarmcheck::mission::load_mission(SWARMCHECK_SCENARIOS "/thesis/thesis-mission.json");
  run(st, "thesis", m);
}
BENCHMARK(BM_Thesis)->Unit(benchmark::kMillisecond);

void BM_Allocation(benchmark::State& st) {
  run(st, key_of(st), allocation(std::size_t(st.range(0)), std::size_t(st.range(1))));
}
BENCHMARK(BM_Allocation)
    ->Args({2, 4})->Args({3, 4})->Args({4, 4})->Args({5, 4})->Args({6, 4})
    ->ArgNames({"robots", "tasks"})->Unit(benchmark::kMillisecond);

// Same generator, sizes where only the exact planner runs; states 14 336 .. 177 664.
void BM_AllocationLarge(benchmark::State& st) { BM_Allocation(st); }
BENCHMARK(BM_AllocationLarge)
    ->Args({2, 9})->Args({2, 11})->Args({3, 9})->Args({3, 10})->Args({4, 8})->Args({5, 7})
    ->Args({6, 6})
    ->ArgNames({"robots", "tasks"})->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
