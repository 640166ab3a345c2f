// swarmcheck run: one exploration run, summary on stdout, optional JSON Lines trace.
#include "apps/swarmcheck/run_verb.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <chrono>
#include <memory>
#include <optional>

#include "impl/io/atomic_file.hpp"
#include "apps/swarmcheck/verb.hpp"
#include "conformance/exploration/engine.hpp"
#include "conformance/exploration/summary.hpp"
#include "swarmcheck/exploration.hpp"
#include "spec/exploration/scenario.hpp"
#include "spec/exploration/trace.hpp"
#include "views/run_recorder.hpp"

namespace swarmcheck::cli {
namespace {

using namespace swarmcheck::exploration;
namespace cx = swarmcheck::conformance::exploration;

struct RunOptions {
  std::string scenario_path;   // empty: the built-in default
  std::string mode, rule;      // empty: as in the scenario
  std::optional<uint64_t> seed;
  std::optional<int64_t> steps;
  std::string trace_path;
  int64_t trace_every = 1;
  int64_t trace_field = 0;     // 0: no field records
  std::string svg_path;
  std::string engine = "impl";
  bool json = false;
};

Scenario resolve_scenario(const RunOptions& o) {
  Scenario s = o.scenario_path.empty() ? default_scenario() : load_scenario(o.scenario_path);
  const std::string where = o.scenario_path.empty() ? "default scenario" : o.scenario_path;
  if (!o.mode.empty()) s.mode = json_io::enum_from_string<Mode>(o.mode, "--mode");
  if (!o.rule.empty()) s.rule = json_io::enum_from_string<RuleSet>(o.rule, "--rule");
  if (o.seed) s.seed = *o.seed;
  if (o.steps) s.max_steps = *o.steps;
  try {
    validate(s);   // the overrides can make a valid file invalid (e.g. cosim step_size)
  } catch (const InputError& e) {
    throw InputError(where + " with the command-line overrides: " + e.where(),
                     std::string(e.what()).substr(e.where().size() + 2));
  }
  return s;
}

class Progress {
 public:
  Progress() : enabled_(::isatty(2) == 1), last_(std::chrono::steady_clock::now()) {}
  void update(int64_t step, double eP, int64_t max_steps) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    fmt::print(stderr, "\rstep {:>9} / {}  eP {:6.2f} %   ", step, max_steps, eP);
  }
  void finish() {
    if (enabled_) fmt::print(stderr, "\r{:80}\r", "");
  }

 private:
  bool enabled_;
  std::chrono::steady_clock::time_point last_;
};

void print_summary(const Scenario& s, const RunOptions& o, const cx::Simulation& sim) {
  if (o.json) {
    json_io::Json j = cx::run_summary(sim);
    j["engine"] = o.engine;
    fmt::print("{}\n", j.dump());
    return;
  }
  const auto completion = sim.completion_step();
  const double eP = sim.eP(), sTime = sim.sTime();
  const int64_t steps = sim.steps(), planning_steps = sim.planning_steps(), visited = sim.visited(),
                free_cells = sim.free_cells();
  fmt::print("swarmcheck run: {} (map {}x{}, {} robots, {} obstacles), rule {}, mode {}, seed {}\n",
             o.scenario_path.empty() ? "default scenario" : o.scenario_path, s.map_size,
             s.map_size, s.robots.size(), s.obstacles.size(), json_io::enum_to_string(s.rule),
             json_io::enum_to_string(s.mode), s.seed);
  if (completion)
    fmt::print("completed at step {} (sTime {:.1f} s): eP {:.2f} %, {} / {} free cells visited, "
               "{} planning steps\n",
               *completion, sTime, eP, visited, free_cells, planning_steps);
  else
    fmt::print("not complete after {} steps (max_steps): eP {:.2f} %, {} / {} free cells "
               "visited, {} planning steps\n",
               steps, eP, visited, free_cells, planning_steps);
}

// Runs either engine (the library, or the reference model through the harness).
int run_with(conformance::exploration::Simulation& sim, const Scenario& s, const RunOptions& o) {
  impl::io::refuse_output_that_is_an_input(o.trace_path, {o.scenario_path});
  impl::io::refuse_output_that_is_an_input(o.svg_path, {o.scenario_path, o.trace_path});
  std::unique_ptr<impl::io::AtomicFile> trace;
  if (!o.trace_path.empty()) trace = std::make_unique<impl::io::AtomicFile>(o.trace_path);
  views::RunRecorder recorder(s, {o.trace_field, o.svg_path, o.scenario_path.empty() ? "default scenario" : o.scenario_path},
                              trace ? &trace->stream() : nullptr);
  if (trace) {
    trace->stream() << recorder.header(trace_header(s)).dump() << '\n';
    trace->stream() << trace_line(sim.record()) << '\n';
  }
  recorder.observe(sim);
  Progress progress;
  while (!sim.done()) {
    sim.step();
    if (trace && (sim.steps() % o.trace_every == 0 || sim.done())) trace->stream() << trace_line(sim.record()) << '\n';
    recorder.observe(sim);
    if (sim.steps() % 4096 == 0) progress.update(sim.steps(), sim.eP(), s.max_steps);
  }
  progress.finish();
  recorder.finish(sim);
  if (trace) trace->commit();
  print_summary(s, o, sim);
  return 0;
}

int run(const RunOptions& o) {
  if (o.trace_every < 1) throw InputError("--trace-every", "expected an integer >= 1");
  if (o.trace_field < 0) throw InputError("--trace-field", "expected an integer >= 1");
  if (o.trace_field > 0 && o.trace_path.empty()) throw InputError("--trace-field", "needs --trace FILE");
  const Scenario s = resolve_scenario(o);
  const auto sim = cx::make_simulation(o.engine == "model" ? cx::Engine::model : cx::Engine::impl, s);
  return run_with(*sim, s, o);
}

}  // namespace

void add_run_verb(CLI::App& app, int& exit_code) {
  auto opts = std::make_shared<RunOptions>();
  CLI::App* cmd = app.add_subcommand(
      "run", "Run one exploration (the built-in thesis set-up when no file is given)");
  cmd->add_option("scenario", opts->scenario_path, "Scenario file (JSON); see README")
      ->check(CLI::ExistingFile);
  cmd->add_option("--mode", opts->mode, "abstract | cosim (overrides the file)")
      ->check(CLI::IsMember({"abstract", "cosim"}));
  std::vector<std::string> rules;   // the rule sets' table (spec/exploration/rule_set.hpp)
  for (const auto& row : swarmcheck::exploration::kRuleSets) rules.emplace_back(row.name);
  cmd->add_option("--rule", opts->rule,
                  "The rule set (overrides the file)")
      ->check(CLI::IsMember(rules));
  cmd->add_option("--seed", opts->seed, "The run's one seed (overrides the file)")->check(seed_validator());
  cmd->add_option("--steps", opts->steps, "Master steps at most (overrides max_steps)");
  cmd->add_option("--trace", opts->trace_path, "Write the JSON Lines trace to FILE");
  cmd->add_option("--trace-every", opts->trace_every, "Record every K-th step in the trace")
      ->capture_default_str();
  cmd->add_option("--trace-field", opts->trace_field,
                  "Also record the whole pheromone field and the visited set every K steps (trace format 2)");
  cmd->add_option("--svg", opts->svg_path, "Write a picture of the end of the run (coverage, pheromone, paths)");
  cmd->add_option("--engine", opts->engine, "impl (the optimised library) | model (the reference)")
      ->check(CLI::IsMember({"impl", "model"}))
      ->capture_default_str();
  cmd->add_flag("--json", opts->json, "Print the summary as one JSON object");
  cmd->callback([opts, &exit_code] { exit_code = guarded([&] { return run(*opts); }); });
}

}  // namespace swarmcheck::cli
