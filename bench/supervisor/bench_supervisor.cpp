// Product and supervisor synthesis, impl against model in one run, on two generated families
// (each a plant and a specification, built as values with spec/supervisor's Automaton):
//
// line(n): a transfer line of n machines (start a_i controllable, finish b_i uncontrollable)
//   with a one-slot buffer between neighbours (spec: no overflow, no underflow). Plant: 2^n
//   states; plant || spec: 2^(2n-1) states (n = 11: 2 097 152).
// ring(n, k): n robots on a two-way ring of k regions. Robot i idles in a region, starts to
//   move forwards or backwards (f_i, b_i: controllable) and enters the adjacent region
//   (cw_i_j, ccw_i_j: uncontrollable, the world decides when). Spec, one automaton per region:
//   empty / occupied, so a robot never enters an occupied region (the thesis's avoidance rule).
//   Plant: (3k)^n states. Robots cannot pass each other, so plant || spec has
//   C(k, n) * n * 3^n states (positions in cyclic order, each robot idle or moving either way):
//   (5, 13): 1 563 705. Synthesis needs the plant as one automaton, (3k)^n states, which caps
//   its sizes lower ((4, 12): 1.68 M plant states, 160 380 product states).
//
// BM_Product times the product of all spec and plant parts (spec first: the model folds the
// product left to right, and the spec keeps its intermediates small); BM_Synthesis times
// supcon(plant, spec) (the products of the parts built beforehand, untimed). Each reports the
// sizes as counters (states of the result; product_states and plant_states for synthesis)
// and, where the model is affordable (at most the registration's model_max states: the model
// under about 20 s), model_ms and model/impl. The model is timed once per size (cached), not
// once per Google Benchmark calibration round.
// GCC 12 reports a false -Wrestrict inside std::string (GCC bug 105329) on this file's
// string building; it is a known compiler bug, not a finding.
#pragma GCC diagnostic ignored "-Wrestrict"
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <map>

#include "impl/supervisor/operations.hpp"
#include "model/supervisor/operations.hpp"

namespace {

namespace impl = swarmcheck::impl::supervisor;
namespace model = swarmcheck::model::supervisor;
using swarmcheck::supervisor::Automaton;

// The model is run while its result (product) or product (synthesis) has at most `model_max`
// states, a per-family bound chosen to keep it under about 20 s: on the line its product costs
// ~30 us a state and its synthesis grows about quadratically (10 s at 32 768 product states);
// on the ring (many parts, a large alphabet) its product takes ~50 s at 22 680 states.

std::string num(const char* p, int i) {
  std::string s = p;
  s += std::to_string(i);
  return s;
}
std::string num2(const char* p, int i, int j) {
  std::string s = num(p, i);
  s += '_';
  s += std::to_string(j);
  return s;
}

struct Family {
  std::vector<Automaton> plant, spec;
};

// ---- line(n): machines with one-slot buffers --------------------------------------------

Automaton machine(int i) {
  Automaton m;
  m.states = {"I", "W"};
  m.marked = {"I"};
  m.events[num("a", i)] = {true, true};
  m.events[num("b", i)] = {false, true};
  m.delta["I"][num("a", i)] = "W";
  m.delta["W"][num("b", i)] = "I";
  return m;
}

// Buffer between machine i and i+1: filled by b_i, emptied by a_{i+1}.
Automaton buffer(int i) {
  Automaton b;
  b.states = {"E", "F"};
  b.marked = {"E"};
  b.events[num("b", i)] = {false, true};
  b.events[num("a", i + 1)] = {true, true};
  b.delta["E"][num("b", i)] = "F";
  b.delta["F"][num("a", i + 1)] = "E";
  return b;
}

Family line(int n, int /*unused*/) {
  Family f;
  for (int i = 0; i < n; ++i) f.plant.push_back(machine(i));
  for (int i = 0; i + 1 < n; ++i) f.spec.push_back(buffer(i));
  return f;
}

// ---- ring(n, k): robots on a two-way ring of regions -------------------------------------

int ring_start(int i, int n, int k) { return i * k / n; }  // robots spread over the ring

// Robot i: I<j> idle in region j (marked); F<j> / B<j> moving out of j (still in j) forwards to
// j+1 / backwards to j-1. f_i: I<j> -> F<j> and b_i: I<j> -> B<j> (controllable starts);
// cw_i_<j>: F<j> -> I<j+1> and ccw_i_<j>: B<j> -> I<j-1> (uncontrollable entries).
Automaton robot(int i, int n, int k) {
  Automaton r;
  const int p = ring_start(i, n, k);
  for (int d = 0; d < k; ++d) r.states.push_back(num("I", (p + d) % k));  // I<p> first: initial
  for (int j = 0; j < k; ++j) r.states.push_back(num("F", j));
  for (int j = 0; j < k; ++j) r.states.push_back(num("B", j));
  r.events[num("f", i)] = {true, true};
  r.events[num("b", i)] = {true, true};
  for (int j = 0; j < k; ++j) {
    const std::string cw = num2("cw", i, j), ccw = num2("ccw", i, j);
    r.marked.insert(num("I", j));
    r.events[cw] = {false, true};
    r.events[ccw] = {false, true};
    r.delta[num("I", j)][num("f", i)] = num("F", j);
    r.delta[num("I", j)][num("b", i)] = num("B", j);
    r.delta[num("F", j)][cw] = num("I", (j + 1) % k);
    r.delta[num("B", j)][ccw] = num("I", (j + k - 1) % k);
  }
  return r;
}

// Region j: E (empty) / F (occupied), both marked. A robot entering j (cw from j-1, ccw from
// j+1) fills it, a robot leaving it (cw or ccw from j) empties it. No entry while F: the
// avoidance rule. Two robots heading for the same empty region from both sides is a race the
// supervisor must prevent at the starts, the entries being uncontrollable.
Automaton region(int j, int n, int k) {
  Automaton g;
  bool occupied = false;
  for (int i = 0; i < n; ++i) occupied = occupied || ring_start(i, n, k) == j;
  g.states = occupied ? std::vector<std::string>{"F", "E"} : std::vector<std::string>{"E", "F"};
  g.marked = {"E", "F"};
  for (int i = 0; i < n; ++i) {
    const std::string in_cw = num2("cw", i, (j + k - 1) % k), in_ccw = num2("ccw", i, (j + 1) % k);
    const std::string out_cw = num2("cw", i, j), out_ccw = num2("ccw", i, j);
    for (const auto& e : {in_cw, in_ccw, out_cw, out_ccw}) g.events[e] = {false, true};
    g.delta["E"][in_cw] = "F";
    g.delta["E"][in_ccw] = "F";
    g.delta["F"][out_cw] = "E";
    g.delta["F"][out_ccw] = "E";
  }
  return g;
}

Family ring(int n, int k) {
  Family f;
  for (int i = 0; i < n; ++i) f.plant.push_back(robot(i, n, k));
  for (int j = 0; j < k; ++j) f.spec.push_back(region(j, n, k));
  return f;
}

// ---- harness ------------------------------------------------------------------------------

using Make = Family (*)(int, int);

std::vector<impl::Fsm> compile_all(const std::vector<Automaton>& v) {
  std::vector<impl::Fsm> out;
  for (const auto& a : v) out.push_back(impl::compile(a));
  return out;
}
std::vector<const impl::Fsm*> ptrs(const std::vector<impl::Fsm>& v) {
  std::vector<const impl::Fsm*> out;
  for (const auto& f : v) out.push_back(&f);
  return out;
}
std::vector<std::string> names(std::size_t k) { return std::vector<std::string>(k, "part"); }

template <class F>
double time_ms(F f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// The model's time for one benchmark and size, measured on first use only.
template <class F>
double model_once(const std::string& key, F f) {
  static std::map<std::string, double> cache;
  const auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  return cache[key] = time_ms(f);
}

std::string key_of(const char* op, const benchmark::State& state) {
  return std::string(op) + "/" + std::to_string(state.range(0)) + "/" +
         std::to_string(state.range(1));
}

void report(benchmark::State& state, double impl_s, double model_ms, std::size_t states) {
  const double impl_ms =
      state.iterations() ? 1e3 * impl_s / static_cast<double>(state.iterations()) : NAN;
  state.counters["states"] = static_cast<double>(states);
  state.counters["model_ms"] = model_ms;
  state.counters["model/impl"] = model_ms / impl_ms;
}

// Product of all spec and plant parts (the closed-loop uncontrolled system).
void BM_Product(benchmark::State& state, Make make, std::size_t model_max) {
  const Family fam = make(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  std::vector<Automaton> parts = fam.spec;
  parts.insert(parts.end(), fam.plant.begin(), fam.plant.end());
  const std::vector<impl::Fsm> all = compile_all(parts);
  std::size_t states = 0;
  double impl_s = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    const impl::Fsm p = impl::product(ptrs(all), names(all.size()));
    impl_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    states = p.state_count();
    benchmark::DoNotOptimize(p.edge_count());
  }
  double model_ms = NAN;
  if (states <= model_max)
    model_ms = model_once(key_of(make == &line ? "line-product" : "ring-product", state), [&] {
      benchmark::DoNotOptimize(model::product(parts, names(parts.size())));
    });
  report(state, impl_s, model_ms, states);
}

// Supervisor: plant = product of the plant parts, spec = product of the spec parts.
void BM_Synthesis(benchmark::State& state, Make make, std::size_t model_max) {
  const Family fam = make(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  const std::vector<impl::Fsm> fp = compile_all(fam.plant), fs = compile_all(fam.spec);
  const impl::Fsm g = impl::product(ptrs(fp), names(fp.size()));
  const impl::Fsm s = impl::product(ptrs(fs), names(fs.size()));
  std::size_t states = 0;
  double impl_s = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    const impl::Fsm sup = impl::supcon(g, s);
    impl_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    states = sup.state_count();
  }
  static std::map<std::string, std::size_t> product_cache;
  const std::string key = key_of(make == &line ? "line-synthesis" : "ring-synthesis", state);
  if (!product_cache.count(key))
    product_cache[key] = impl::product({&g, &s}, {"plant", "spec"}).state_count();
  const std::size_t product_states = product_cache[key];
  double model_ms = NAN;
  if (product_states <= model_max) {
    const Automaton mg = impl::decompile(g), ms = impl::decompile(s);
    model_ms = model_once(key, [&] { benchmark::DoNotOptimize(model::supcon(mg, ms)); });
  }
  report(state, impl_s, model_ms, states);
  state.counters["product_states"] = static_cast<double>(product_states);
  state.counters["plant_states"] = static_cast<double>(g.state_count());
}

// line: n = 4..11 (product 2^(2n-1) states: 128 .. 2 097 152); the model up to n = 8.
BENCHMARK_CAPTURE(BM_Product, line, &line, 40'000)
    ->ArgsProduct({{4, 6, 8, 10, 11}, {0}})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Synthesis, line, &line, 40'000)
    ->ArgsProduct({{4, 6, 8, 10, 11}, {0}})->Unit(benchmark::kMillisecond);
// ring: (robots, regions). Product states 270, 4 536, 22 680, 68 040, 1 563 705 (the model up
// to (3, 8)); synthesis: plant states 324 .. 1 679 616, product states 270 .. 160 380 (the
// model up to (4, 8)).
BENCHMARK_CAPTURE(BM_Product, ring, &ring, 5'000)
    ->Args({2, 6})->Args({3, 8})->Args({4, 8})->Args({4, 10})->Args({5, 13})
    ->ArgNames({"robots", "regions"})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Synthesis, ring, &ring, 25'000)
    ->Args({2, 6})->Args({3, 6})->Args({3, 8})->Args({4, 8})->Args({4, 12})
    ->ArgNames({"robots", "regions"})->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
