// bench_exploration: the optimised library against the reference model, in one run.
//
// Each benchmark iteration is one master step of an already built simulation (construction is
// not timed). abstract: every step is a planning step (robot decisions/s); cosim: Environment +
// controllers + bodies at dt = 0.1 s (x_realtime = simulated seconds per wall second). The model
// runs on one thread; the impl twice: on one thread (impl1) and with the options `swarmcheck run`
// uses by default (impl: every core). At the end a table gives, per size, both impl times, the
// model's, model / impl (as the CLI runs it, and on one thread) and the speed-up from threads.
// load/r1000000/n1024 times reading, validating and building a 10^6-robot scenario.
// threads/... run one thread and every core side by side (threads_ab.hpp): the speed-up from
// threads as the CLI runs, with the schedules forced, and the decision stage's ceiling with no
// schedule at all; a second table.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <memory>
#include <numeric>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "bench/exploration/threads_ab.hpp"
#include "model/exploration/exploration_model.hpp"
#include "spec/exploration/rng.hpp"
#include "spec/exploration/scenario.hpp"
#include "swarmcheck/exploration.hpp"

namespace {

using namespace swarmcheck;
using namespace swarmcheck::exploration;

// R robots on distinct cells of an N x N map, chosen by a seeded partial shuffle.
Scenario bench_scenario(Mode mode, int32_t robots, int32_t map_size) {
  Scenario s = default_scenario();
  s.mode = mode;
  s.map_size = map_size;
  s.obstacles.clear();
  s.robots.clear();
  s.max_steps = kStepsMax;
  const int64_t cells = int64_t{map_size} * map_size;
  // A sparse Fisher-Yates over [0, cells): only the swapped positions are kept (a hash map: with
  // 10^6 robots, a std::map here was half of a profile of the bench's set-up).
  std::unordered_map<int64_t, int64_t> swapped;
  swapped.reserve(static_cast<std::size_t>(2 * robots));
  for (int64_t k = 0; k < robots; ++k) {
    const int64_t j = k + static_cast<int64_t>(splitmix64(static_cast<uint64_t>(k) + 7) % static_cast<uint64_t>(cells - k));
    const auto at = [&](int64_t p) { const auto it = swapped.find(p); return it == swapped.end() ? p : it->second; };
    const int64_t at_j = at(j);
    const int64_t at_k = at(k);
    swapped[j] = at_k;
    s.robots.push_back({static_cast<double>(at_j / map_size) + 0.5, static_cast<double>(at_j % map_size) + 0.5});
  }
  validate(s);
  return s;
}

ExplorationOptions one_thread() {
  ExplorationOptions o;
  o.threads = 1;
  return o;
}

template <class Sim>
void run_steps(benchmark::State& state, Sim& sim, const Scenario& s) {
  for (auto _ : state) sim.step();
  const double steps = static_cast<double>(state.iterations());
  state.counters["steps_per_s"] = benchmark::Counter(steps, benchmark::Counter::kIsRate);
  state.counters["decisions_per_s"] =
      benchmark::Counter(s.mode == Mode::abstract ? steps * static_cast<double>(s.robots.size()) : 0.0,
                         benchmark::Counter::kIsRate);
  state.counters["x_realtime"] = benchmark::Counter(steps * s.params.step_size, benchmark::Counter::kIsRate);
}

// The published robot: cosim with the 20-sim body (100 RK4 steps a robot a master step) and
// the swarmcheck controller.
Scenario intocps_scenario(int32_t robots, int32_t map_size) {
  Scenario s = bench_scenario(Mode::cosim, robots, map_size);
  s.body.kind = BodyKind::intocps;
  validate(s);
  return s;
}

void bench_intocps(benchmark::State& state, int32_t robots, int32_t map, bool one) {
  const Scenario s = intocps_scenario(robots, map);
  ExplorationOptions o;
  if (one) o.threads = 1;
  Exploration x(s, o);
  run_steps(state, x, s);
  state.counters["robot_substeps_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * robots * 100.0, benchmark::Counter::kIsRate);
}

void bench_intocps_model(benchmark::State& state, int32_t robots, int32_t map) {
  const Scenario s = intocps_scenario(robots, map);
  auto m = std::make_unique<swarmcheck::model::exploration::ExplorationModel>(s);
  run_steps(state, *m, s);
}

void bench_impl1(benchmark::State& state, Mode mode, int32_t robots, int32_t map) {
  const Scenario s = bench_scenario(mode, robots, map);
  Exploration x(s, one_thread());
  run_steps(state, x, s);
}

// As `swarmcheck run` runs it: default options (every core).
void bench_impl(benchmark::State& state, Mode mode, int32_t robots, int32_t map) {
  const Scenario s = bench_scenario(mode, robots, map);
  Exploration x(s, ExplorationOptions{});
  run_steps(state, x, s);
}

// The scenario as a file's text, then what `swarmcheck run FILE` does before its first step.
void bench_load(benchmark::State& state, int32_t robots, int32_t map) {
  const std::string text = json_io::to_json(bench_scenario(Mode::abstract, robots, map)).dump();
  for (auto _ : state) {
    const ValidScenario s = parse_valid_scenario(text, "bench.json");   // validated once, here
    Exploration x(s, ExplorationOptions{});
    benchmark::DoNotOptimize(x.visited());
  }
  state.counters["bytes"] = static_cast<double>(text.size());
}

void bench_model(benchmark::State& state, Mode mode, int32_t robots, int32_t map) {
  const Scenario s = bench_scenario(mode, robots, map);
  auto m = std::make_unique<swarmcheck::model::exploration::ExplorationModel>(s);
  run_steps(state, *m, s);
}

// Console output as usual, plus the ratio table at the end.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      const std::string name = r.run_name.function_name;
      const auto slash = name.find('/');
      const std::string engine = name.substr(0, slash), size = name.substr(slash + 1);
      // With --benchmark_repetitions the median stands for the runs (it is reported after them).
      if (engine == "load" || (r.run_type == Run::RT_Aggregate && r.aggregate_name != "median")) continue;
      if (engine == "threads") {
        const auto c = [&](const char* k) { const auto it = r.counters.find(k); return it == r.counters.end() ? 0.0 : it->second.value; };
        threads_[size] = {c("one_us"), c("all_us"), c("speedup"), c("share_slowdown")};
        continue;
      }
      (engine == "impl" ? impl_ : engine == "impl1" ? impl1_ : model_)[size] = r.GetAdjustedRealTime();   // us
    }
  }
  void Finalize() override {
    ConsoleReporter::Finalize();
    std::printf("\n%-26s %12s %12s %14s %10s %10s %9s\n", "mode/robots/map", "impl us/step", "impl1 us/step",
                "model us/step", "model/impl", "model/impl1", "threads");
    for (const auto& [size, impl_us] : impl_) {
      const auto one = impl1_.find(size);
      const double impl1_us = one == impl1_.end() ? 0.0 : one->second;
      const auto m = model_.find(size);
      if (m == model_.end())
        std::printf("%-26s %12.2f %12.2f %14s %10s %10s %8.2fx\n", size.c_str(), impl_us, impl1_us, "-", "-", "-",
                    impl1_us / impl_us);
      else
        std::printf("%-26s %12.2f %12.2f %14.2f %9.1fx %9.1fx %8.2fx\n", size.c_str(), impl_us, impl1_us, m->second,
                    m->second / impl_us, m->second / impl1_us, impl1_us / impl_us);
    }
    if (threads_.empty()) return;
    std::printf("\n%-34s %12s %12s %9s %15s   (side by side: threads_ab.hpp)\n", "threads/variant/mode/robots/map",
                "1 thread us", "all us", "speed-up", "share slowdown");
    for (const auto& [size, t] : threads_) {
      std::printf("%-34s %12.2f %12.2f %8.2fx", size.c_str(), t.one_us, t.all_us, t.speedup);
      if (t.share_slowdown > 0) std::printf(" %14.2fx", t.share_slowdown);
      std::printf("\n");
    }
  }

 private:
  std::map<std::string, double> impl_, impl1_, model_;
  struct SideBySide {
    double one_us, all_us, speedup, share_slowdown;   // share_slowdown: ceiling rows only
  };
  std::map<std::string, SideBySide> threads_;
};

void register_all() {
  const int32_t robot_counts[] = {10, 100, 1000, 10000};
  const int32_t maps[] = {64, 256, 1024, 4096};
  for (Mode mode : {Mode::abstract, Mode::cosim})
    for (int32_t map : maps)
      for (int32_t robots : robot_counts) {
        if (int64_t{robots} * 4 > int64_t{map} * map) continue;   // at most a quarter of the cells
        const std::string size = std::string(mode == Mode::abstract ? "abstract" : "cosim") + "/r" +
                                 std::to_string(robots) + "/n" + std::to_string(map);
        benchmark::RegisterBenchmark(("impl/" + size).c_str(), bench_impl, mode, robots, map)
            ->Unit(benchmark::kMicrosecond)->MinTime(0.2);
        benchmark::RegisterBenchmark(("impl1/" + size).c_str(), bench_impl1, mode, robots, map)
            ->Unit(benchmark::kMicrosecond)->MinTime(0.2);
        // The model's step is O(cells): run it where a step takes well under a second.
        const bool model_fits = int64_t{map} * map <= (mode == Mode::abstract ? 4096 * 4096 : 1024 * 1024);
        if (model_fits)
          benchmark::RegisterBenchmark(("model/" + size).c_str(), bench_model, mode, robots, map)
              ->Unit(benchmark::kMicrosecond)->MinTime(0.2);
      }
  // The 20-sim body (cosim, body intocps): the four-robot lanes against the model's scalar step.
  for (const auto& [robots, map] : {std::pair{10, 64}, std::pair{100, 64}, std::pair{1000, 256}, std::pair{10000, 256}}) {
    const std::string size = "intocps/r" + std::to_string(robots) + "/n" + std::to_string(map);
    benchmark::RegisterBenchmark(("impl/" + size).c_str(), bench_intocps, robots, map, false)
        ->Unit(benchmark::kMicrosecond)->MinTime(0.2);
    benchmark::RegisterBenchmark(("impl1/" + size).c_str(), bench_intocps, robots, map, true)
        ->Unit(benchmark::kMicrosecond)->MinTime(0.2);
    if (robots <= 1000)
      benchmark::RegisterBenchmark(("model/" + size).c_str(), bench_intocps_model, robots, map)
          ->Unit(benchmark::kMicrosecond)->MinTime(0.2);
  }
  // 10^6 robots on 1024^2: loading, and steps as the CLI runs them and on one thread.
  benchmark::RegisterBenchmark("load/r1000000/n1024", bench_load, 1'000'000, 1024)->Unit(benchmark::kMillisecond)->Iterations(3);
  benchmark::RegisterBenchmark("impl/abstract/r1000000/n1024", bench_impl, Mode::abstract, 1'000'000, 1024)
      ->Unit(benchmark::kMicrosecond)->MinTime(1.0);
  benchmark::RegisterBenchmark("impl1/abstract/r1000000/n1024", bench_impl1, Mode::abstract, 1'000'000, 1024)
      ->Unit(benchmark::kMicrosecond)->MinTime(1.0);
  // Threads side by side with one thread, on the layouts of impl/abstract/...: as the CLI runs,
  // with the schedules forced, and the decision stage's ceiling.
  ExplorationOptions strips;
  strips.parallel_min_robots = 1;
  for (const auto& [robots, map] : {std::pair{10'000, 256}, std::pair{10'000, 1024}, std::pair{10'000, 4096},
                                    std::pair{1'000'000, 1024}}) {
    const std::string size = "abstract/r" + std::to_string(robots) + "/n" + std::to_string(map);
    const Scenario s = bench_scenario(Mode::abstract, robots, map);
    const double min_time = robots >= 1'000'000 ? 2.0 : 0.5;
    benchmark::RegisterBenchmark(("threads/cli/" + size).c_str(), swarmcheck::bench::bench_threads_steps, s,
                                 ExplorationOptions{})->Unit(benchmark::kMicrosecond)->MinTime(min_time);
    benchmark::RegisterBenchmark(("threads/strips/" + size).c_str(), swarmcheck::bench::bench_threads_steps, s, strips)
        ->Unit(benchmark::kMicrosecond)->MinTime(min_time);
    benchmark::RegisterBenchmark(("threads/ceiling/" + size).c_str(), swarmcheck::bench::bench_threads_ceiling, s)
        ->Unit(benchmark::kMicrosecond)->MinTime(min_time);
  }
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
