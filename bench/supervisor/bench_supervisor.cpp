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
//
// The command line's paths at 10^6 states (impl only: the model would take hours), each timed
// once from its input to its output: BM_CheckText (read + check, `fsm check`) on a chain and a
// binary tree; BM_ProductSummary (product + .fsm text, and with the --json summary's nonblocking
// check: json/plain is the ratio the summary costs); BM_Compare (inclusion both ways of two
// n x n grid supervisors that differ at the far corner); BM_TransferLine (Wonham's transfer
// line M1 -> B1 -> M2 -> B2 -> TU, rejects back to B1, buffers of n slots: synthesis and the
// .fsm text). peak_MB is the process's peak resident memory during the case (VmHWM after
// resetting it through /proc/self/clear_refs), its inputs included; added_MB the peak over what
// was resident when the case started.
// GCC 12 reports a false -Wrestrict inside std::string (GCC bug 105329) on this file's
// string building; it is a known compiler bug, not a finding.
#pragma GCC diagnostic ignored "-Wrestrict"
#include <benchmark/benchmark.h>

#include <malloc.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <streambuf>

#include "impl/supervisor/fsm_compact_io.hpp"
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

// ---- the command line's paths at 10^6 states --------------------------------------------

// A stream that only counts what is written: the .fsm text's cost without the disk's.
class CountingBuffer : public std::streambuf {
 public:
  std::size_t bytes = 0;

 protected:
  int_type overflow(int_type c) override {
    ++bytes;
    return c;
  }
  std::streamsize xsputn(const char*, std::streamsize n) override {
    bytes += static_cast<std::size_t>(n);
    return n;
  }
};

// A field of /proc/self/status in MB (VmRSS: now; VmHWM: the peak since the last reset), NaN
// where Linux's /proc is not.
double status_mb(const char* field) {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind(field, 0) == 0) return std::stod(line.substr(std::strlen(field))) / 1024.0;
  return NAN;
}
// Earlier cases' freed memory is handed back first (malloc_trim), else the process's resident
// size, and so the peak, would stay at the largest earlier case. Returns the resident MB now.
double reset_peak_rss() {
  malloc_trim(0);
  std::ofstream("/proc/self/clear_refs") << "5";
  return status_mb("VmRSS:");
}
void report_peak(benchmark::State& state, double base_mb) {
  state.counters["peak_MB"] = status_mb("VmHWM:");
  state.counters["added_MB"] = status_mb("VmHWM:") - base_mb;  // over the inputs held before
}

std::string chain_text(int n) {
  std::string t = std::to_string(n) + "\n\n";
  for (int i = 0; i < n; ++i) {
    t += num("s", i) + (i + 1 == n ? "\t1\t0\n\n" : "\t0\t1\n");
    if (i + 1 < n) t += "a\t" + num("s", i + 1) + "\tc\to\n\n";
  }
  return t;
}

std::string tree_text(int n) {
  std::string t = std::to_string(n) + "\n\n";
  for (int i = 0; i < n; ++i) {
    const int kids = (2 * i + 1 < n) + (2 * i + 2 < n);
    t += num("t", i) + (kids ? "\t0\t" : "\t1\t") + std::to_string(kids) + "\n";
    if (kids >= 1) t += "l\t" + num("t", 2 * i + 1) + "\tc\to\n";
    if (kids == 2) t += "r\t" + num("t", 2 * i + 2) + "\tuc\to\n";
    t += "\n";
  }
  return t;
}

void BM_CheckText(benchmark::State& state, std::string (*make)(int)) {
  const std::string text = make(static_cast<int>(state.range(0)));
  std::size_t blocking = 0;
  for (auto _ : state) {
    const impl::Fsm f = impl::read_fsm_compact(text, "bench.fsm");
    blocking = impl::check(f).blocking_states.size();
  }
  state.counters["states"] = static_cast<double>(state.range(0));
  state.counters["blocking"] = static_cast<double>(blocking);
}

// A cycle of n states counting `event`, state 0 marked: two of them have an n x n product.
Automaton counter(int n, const std::string& event) {
  Automaton c;
  c.events[event] = {true, true};
  for (int i = 0; i < n; ++i) c.states.push_back(num("q", i));
  c.marked = {"q0"};
  for (int i = 0; i < n; ++i) c.delta[num("q", i)][event] = num("q", (i + 1) % n);
  return c;
}

void BM_ProductSummary(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const std::vector<impl::Fsm> parts = compile_all({counter(n, "x"), counter(n, "y")});
  double plain_s = 0, summary_s = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    const impl::Product p = impl::product_with_tuples(ptrs(parts), names(2));
    CountingBuffer sink;
    std::ostream out(&sink);
    impl::write_fsm_compact(out, p.fsm, impl::name_speller(p.fsm, &p.names));
    const auto t1 = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(impl::every_state_coaccessible(p.fsm));
    plain_s += std::chrono::duration<double>(t1 - t0).count();
    summary_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
    state.counters["states"] = p.fsm.state_count();
  }
  state.counters["json/plain"] = (plain_s + summary_s) / plain_s;
}

// The n x n grid supervisor (x and y count modulo n); `last` renames x at the far corner.
impl::Fsm grid(int n, bool renamed_corner) {
  std::vector<std::string> ev = {"x", "y"};
  if (renamed_corner) ev.push_back("z");
  impl::Fsm f;
  f.event_names = ev;
  f.controllable.assign(ev.size(), 1);
  f.observable.assign(ev.size(), 1);
  auto id = [n](int x, int y) { return static_cast<impl::StateId>(x * n + y); };
  std::vector<std::vector<std::pair<impl::EventId, impl::StateId>>> edges;
  for (int x = 0; x < n; ++x)
    for (int y = 0; y < n; ++y) {
      f.state_names.push_back(num("q", x) + "." + num("q", y));
      f.marked.push_back(x == 0 && y == 0);
      const bool corner = renamed_corner && x == n - 1 && y == n - 1;
      edges.push_back({{corner ? 2u : 0u, id((x + 1) % n, y)}, {1u, id(x, (y + 1) % n)}});
      if (corner) std::swap(edges.back()[0], edges.back()[1]);  // ascending event ids
    }
  impl::set_edges(f, edges);
  return f;
}

void BM_Compare(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const impl::Fsm a = grid(n, false), b = grid(n, true);
  const double base_mb = reset_peak_rss();
  std::size_t witness = 0;
  for (auto _ : state) {
    const auto ab = impl::language_inclusion(a, b), ba = impl::language_inclusion(b, a);
    witness = ab.closed_witness.size() + ba.closed_witness.size();
  }
  state.counters["states"] = static_cast<double>(n) * n;
  state.counters["witness_events"] = static_cast<double>(witness);
  report_peak(state, base_mb);
}

Automaton two_state(const std::string& rest, const std::string& busy, const std::string& start,
                    const std::vector<std::string>& ends) {
  Automaton m;
  m.states = {rest, busy};
  m.marked = {rest};
  m.events[start] = {true, true};
  m.delta[rest][start] = busy;
  for (const auto& e : ends) {
    m.events[e] = {false, true};
    m.delta[busy][e] = rest;
  }
  return m;
}

Automaton slots(int n, const std::vector<std::string>& fill, const std::string& drain) {
  Automaton b;
  for (int k = 0; k <= n; ++k) b.states.push_back(num("b", k));
  b.marked = {"b0"};
  for (const auto& e : fill) b.events[e] = {false, true};
  b.events[drain] = {true, true};
  for (int k = 0; k <= n; ++k) {
    for (const auto& e : fill)
      if (k < n) b.delta[num("b", k)][e] = num("b", k + 1);
    if (k > 0) b.delta[num("b", k)][drain] = num("b", k - 1);
  }
  return b;
}

void BM_TransferLine(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const std::vector<impl::Fsm> plants = compile_all(
      {two_state("idle", "work", "start1", {"finish1"}), two_state("idle", "work", "start2", {"finish2"}),
       two_state("idle", "test", "start3", {"pass", "reject"})});
  const std::vector<impl::Fsm> specs =
      compile_all({slots(n, {"finish1", "reject"}, "start2"), slots(n, {"finish2"}, "start3")});
  const double base_mb = reset_peak_rss();
  for (auto _ : state) {
    const impl::Fsm plant = impl::product(ptrs(plants), names(plants.size()));
    const impl::Fsm spec = impl::product(ptrs(specs), names(specs.size()));
    const impl::Synthesis s = impl::synthesize(plant, spec);
    CountingBuffer sink;
    std::ostream out(&sink);
    impl::write_fsm_compact(out, s.supervisor, impl::name_speller(s.supervisor, &s.names));
    state.counters["states"] = s.supervisor.state_count();
    state.counters["fsm_MB"] = static_cast<double>(sink.bytes) / (1024.0 * 1024.0);
  }
  report_peak(state, base_mb);
}

BENCHMARK_CAPTURE(BM_CheckText, chain, &chain_text)->Arg(1'000'000)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_CheckText, tree, &tree_text)->Arg(1'000'000)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ProductSummary)->Arg(1000)->Iterations(1)->Unit(benchmark::kMillisecond);  // 10^6 states
BENCHMARK(BM_Compare)->Arg(1000)->Iterations(1)->Unit(benchmark::kMillisecond);         // 10^6 states
// 350 slots: 981 392 supervisor states (about 10^6 closed-loop states).
BENCHMARK(BM_TransferLine)->Arg(350)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
