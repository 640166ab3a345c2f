// Planning time: the exact planner (impl, a fresh Planner each time: no cache) against the
// thesis's modified Dijkstra (model), on the thesis mission and on generated task-allocation
// missions with 2..6 robots. Each impl benchmark reports counters states and ratio =
// baseline time / exact time measured in the same run.
#include <benchmark/benchmark.h>

#include <chrono>

#include "conformance/mission/generate.hpp"
#include "impl/mission/load.hpp"
#include "impl/mission/planner.hpp"
#include "model/mission/thesis_dijkstra.hpp"

namespace {

namespace sm = swarmcheck::spec::mission;

double seconds_of(const std::function<void()>& f, int reps) {
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < reps; ++i) f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / reps;
}

void run(benchmark::State& st, const sm::Mission& m) {
  const auto q = sm::initial_query(m);
  for (auto _ : st) {
    swarmcheck::impl::mission::Planner p(m);
    benchmark::DoNotOptimize(p.plan(q));
  }
  const double exact = seconds_of([&] {
    swarmcheck::impl::mission::Planner p(m);
    benchmark::DoNotOptimize(p.plan(q));
  }, 3);
  const double base = seconds_of([&] { benchmark::DoNotOptimize(swarmcheck::model::mission::thesis_plan(m, q)); }, 1);
  st.counters["states"] = double(m.fsm.states.size());
  st.counters["baseline_ms"] = base * 1e3;
  st.counters["ratio"] = base / exact;
}

void BM_Thesis(benchmark::State& st) {
  static const auto m = swarmcheck::impl::mission::load_mission(SWARMCHECK_SCENARIOS "/thesis/thesis-mission.json");
  run(st, m);
}
BENCHMARK(BM_Thesis)->Unit(benchmark::kMillisecond);

void BM_Allocation(benchmark::State& st) {
  const auto m = swarmcheck::conformance::mission::allocation_mission(
      std::size_t(st.range(0)), std::size_t(st.range(1)), 7);
  run(st, m);
}
BENCHMARK(BM_Allocation)
    ->Args({2, 4})->Args({3, 4})->Args({4, 4})->Args({5, 4})->Args({6, 4})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
