// swarmcheck run: one exploration run, summary on stdout, optional JSON Lines trace.
#include "apps/swarmcheck/run_verb.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <chrono>
#include <memory>
#include <optional>

#include "apps/swarmcheck/output_file.hpp"
#include "apps/swarmcheck/verb.hpp"
#include "model/exploration/exploration_model.hpp"
#include "swarmcheck/exploration.hpp"
#include "spec/exploration/scenario.hpp"
#include "spec/exploration/trace.hpp"

namespace swarmcheck::cli {
namespace {

using namespace swarmcheck::exploration;

struct RunOptions {
  std::string scenario_path;   // empty: the built-in default
  std::string mode, rule;      // empty: as in the scenario
  std::optional<uint64_t> seed;
  std::optional<int64_t> steps;
  std::string trace_path;
  int64_t trace_every = 1;
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

void print_summary(const Scenario& s, const RunOptions& o, int64_t steps, int64_t planning_steps,
                   double eP, double sTime, int64_t visited, int64_t free_cells,
                   std::optional<int64_t> completion) {
  if (o.json) {
    json_io::Json j = json_io::Json::object();
    j["completed"] = completion.has_value();
    j["completion_step"] = completion ? json_io::Json(*completion) : json_io::Json(nullptr);
    j["steps"] = steps;
    j["planning_steps"] = planning_steps;
    j["eP"] = eP;
    j["sTime"] = sTime;
    j["visited"] = visited;
    j["free_cells"] = free_cells;
    j["rule"] = json_io::enum_to_string(s.rule);
    j["mode"] = json_io::enum_to_string(s.mode);
    j["seed"] = s.seed;
    j["map_size"] = s.map_size;
    j["robots"] = s.robots.size();
    j["engine"] = o.engine;
    fmt::print("{}\n", j.dump());
    return;
  }
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

// Runs any engine with the model's interface (step, done, steps, record, completion_step).
template <class Sim>
int run_with(Sim& sim, const Scenario& s, const RunOptions& o) {
  std::unique_ptr<AtomicOutputFile> trace;
  if (!o.trace_path.empty()) {
    trace = std::make_unique<AtomicOutputFile>(o.trace_path);
    trace->stream() << trace_header(s).dump() << '\n';
    trace->stream() << trace_line(sim.record()) << '\n';
  }
  Progress progress;
  while (!sim.done()) {
    sim.step();
    if (trace && (sim.steps() % o.trace_every == 0 || sim.done())) trace->stream() << trace_line(sim.record()) << '\n';
    if (sim.steps() % 4096 == 0) progress.update(sim.steps(), sim.eP(), s.max_steps);
  }
  progress.finish();
  if (trace) trace->commit();
  print_summary(s, o, sim.steps(), sim.planning_steps(), sim.eP(), sim.sTime(), sim.visited(),
                sim.free_cells(), sim.completion_step());
  return 0;
}

// The reference model behind the same interface.
struct ModelEngine {
  explicit ModelEngine(const Scenario& s) : m(s) {}
  model::ExplorationModel m;
  void step() { m.step(); }
  bool done() const { return m.done(); }
  int64_t steps() const { return m.steps(); }
  StepRecord record() const { return m.record(); }
  int64_t planning_steps() const { return m.environment().planning_steps(); }
  double eP() const { return m.environment().eP(); }
  double sTime() const { return m.environment().sTime(); }
  int64_t visited() const { return m.environment().visited(); }
  int64_t free_cells() const { return m.environment().free_cells(); }
  std::optional<int64_t> completion_step() const { return m.environment().completion_step(); }
};

int run(const RunOptions& o) {
  if (o.trace_every < 1) throw InputError("--trace-every", "expected an integer >= 1");
  const Scenario s = resolve_scenario(o);
  if (o.engine == "model") {
    ModelEngine m(s);
    return run_with(m, s, o);
  }
  Exploration x(s);
  return run_with(x, s, o);
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
  cmd->add_option("--rule", opts->rule, "thesis | deterministic | stochastic (overrides the file)")
      ->check(CLI::IsMember({"thesis", "deterministic", "stochastic"}));
  cmd->add_option("--seed", opts->seed, "The run's one seed (overrides the file)");
  cmd->add_option("--steps", opts->steps, "Master steps at most (overrides max_steps)");
  cmd->add_option("--trace", opts->trace_path, "Write the JSON Lines trace to FILE");
  cmd->add_option("--trace-every", opts->trace_every, "Record every K-th step in the trace")
      ->capture_default_str();
  cmd->add_option("--engine", opts->engine, "impl (the optimised library) | model (the reference)")
      ->check(CLI::IsMember({"impl", "model"}))
      ->capture_default_str();
  cmd->add_flag("--json", opts->json, "Print the summary as one JSON object");
  cmd->callback([opts, &exit_code] { exit_code = guarded([&] { return run(*opts); }); });
}

}  // namespace swarmcheck::cli
