// swarmcheck run: one exploration run, summary on stdout, optional JSON Lines trace.
#include "apps/swarmcheck/run_verb.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <chrono>
#include <memory>
#include <optional>

#include "impl/io/atomic_file.hpp"
#include "apps/swarmcheck/robot_options.hpp"
#include "apps/swarmcheck/verb.hpp"
#include "conformance/exploration/engine.hpp"
#include "swarmcheck/exploration.hpp"
#include "swarmcheck/run_report.hpp"
#include "spec/exploration/neighbourhood.hpp"
#include "spec/exploration/reachability.hpp"
#include "spec/exploration/scenario.hpp"
#include "spec/exploration/trace.hpp"
#include "views/run_recorder.hpp"

namespace swarmcheck::cli {
namespace {

using namespace swarmcheck::exploration;
namespace cx = swarmcheck::conformance::exploration;

struct ExplorationRunOptions {
  std::string scenario_path;   // empty: the built-in default
  std::string mode, rule;      // empty: as in the scenario
  RobotChoiceOptions robots;
  std::optional<uint64_t> seed;
  std::optional<int64_t> steps;
  std::string trace_path;
  int64_t trace_every = 1;
  int64_t trace_field = 0;     // 0: no field records
  std::string svg_path;
  std::string engine = "impl";
  bool json = false;
  int64_t stall_window = 100000;   // master steps without a newly visited cell; 0: never stop
  int32_t threads = 0;             // 0: every core
  Budgets budgets;
};

// Validated once (a 10^6-robot file's cells are checked on loading only).
ValidScenario resolve_scenario(const ExplorationRunOptions& o) {
  ValidScenario loaded = o.scenario_path.empty() ? ValidScenario(default_scenario()) : load_valid_scenario(o.scenario_path);
  const std::string where = o.scenario_path.empty() ? "default scenario" : o.scenario_path;
  ScenarioOverrides over;
  if (!o.mode.empty()) over.mode = json_io::enum_from_string<Mode>(o.mode, "--mode");
  apply_robot_choices(o.robots, o.rule, over);
  over.seed = o.seed;
  over.max_steps = o.steps;
  try {
    return with_overrides(std::move(loaded), over);   // they can make a valid file invalid (e.g. cosim step_size)
  } catch (const InputError& e) {
    throw InputError(where + " with the command-line overrides: " + e.where(),
                     std::string(e.what()).substr(e.where().size() + 2));
  }
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

void print_summary(const Scenario& s, const ExplorationRunOptions& o, const cx::Simulation& sim, const RunEnd& end) {
  if (o.json) {
    fmt::print("{}\n", json_io::dump_text(run_report(sim, end, o.engine)));
    return;
  }
  const int64_t reachable = end.reach.reachable_free_cells;
  const double eP_reachable = reachable > 0 ? exploration_percent(sim.visited(), reachable) : 100.0;
  const auto completion = sim.completion_step();
  const double eP = sim.eP(), sTime = sim.sTime();
  const int64_t steps = sim.steps(), planning_steps = sim.planning_steps(), visited = sim.visited(),
                free_cells = sim.free_cells();
  // The controller and body are named when they are not the defaults (they run in cosim mode only).
  const bool robots_named = s.mode == Mode::cosim && (s.controller != ControllerKind::swarmcheck || s.body.kind != BodyKind::kinematic);
  fmt::print("swarmcheck run: {} (map {}x{}, {} robots, {} obstacles), rule {}, mode {}{}, seed {}\n",
             o.scenario_path.empty() ? "default scenario" : o.scenario_path, s.map_size,
             s.map_size, s.robots.size(), s.obstacles.size(), json_io::enum_to_string(s.rule),
             json_io::enum_to_string(s.mode),
             robots_named ? fmt::format(", controller {}, body {}", json_io::enum_to_string(s.controller),
                                        json_io::enum_to_string(s.body.kind))
                          : std::string(),
             s.seed);
  if (completion)
    fmt::print("completed at step {} (sTime {:.1f} s): eP {:.2f} %, {} / {} free cells visited, "
               "{} planning steps\n",
               *completion, sTime, eP, visited, free_cells, planning_steps);
  else if (end.outcome == "stalled")
    fmt::print("stalled after {} steps ({}): eP {:.2f} %, {} / {} free cells visited, {} planning steps\n",
               steps, end.stall_reason, eP, visited, free_cells, planning_steps);
  else
    fmt::print("not complete after {} steps (max_steps): eP {:.2f} %, {} / {} free cells "
               "visited, {} planning steps\n",
               steps, eP, visited, free_cells, planning_steps);
  if (end.reach.unreachable_free_cells > 0)
    fmt::print("reachable free cells: {} visited of {} ({:.2f} %); {} free cells no robot can reach\n",
               visited, reachable, eP_reachable, end.reach.unreachable_free_cells);
}

// The trace's size, estimated from the first record before anything is written: the records
// (every trace_every steps, at most max_steps) and the field records of --trace-field.
double estimated_trace_bytes(const Scenario& s, const ExplorationRunOptions& o, std::size_t first_record_bytes) {
  const double records = static_cast<double>(s.max_steps) / static_cast<double>(o.trace_every) + 2.0;
  double bytes = records * static_cast<double>(first_record_bytes + 1);
  if (o.trace_field > 0) {
    const double cells = static_cast<double>(s.map_size) * s.map_size;
    bytes += (static_cast<double>(s.max_steps) / static_cast<double>(o.trace_field) + 1.0) * cells * 5.0;
  }
  return bytes;
}

// Runs either engine (the library, or the reference model through the harness). Status 0 when
// the run completed, 1 when it stopped at max_steps or stalled.
int run_with(conformance::exploration::Simulation& sim, const Scenario& s, const ExplorationRunOptions& o,
             const Reachability& reach) {
  if (!o.trace_path.empty())
    require_within("--trace " + o.trace_path, "the trace (" + std::to_string(s.max_steps) + " steps at most)",
                   estimated_trace_bytes(s, o, trace_line(sim.record()).size()), o.budgets.trace_bytes,
                   "--max-trace-bytes");
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
  // The loop and its stall rule are the library's (swarmcheck/run_report.hpp), as Python runs it.
  const RunEnd end = run_to_end(sim, reach, o.stall_window, [&](const cx::Simulation& at, bool last) {
    if (trace && (at.steps() % o.trace_every == 0 || last)) trace->stream() << trace_line(at.record()) << '\n';
    recorder.observe(at);
    if (at.steps() % 4096 == 0) progress.update(at.steps(), at.eP(), s.max_steps);
  });
  progress.finish();
  recorder.finish(sim);
  if (trace) trace->commit();
  print_summary(s, o, sim, end);
  return sim.completion_step() ? 0 : 1;
}

int run(const ExplorationRunOptions& o) {
  if (o.trace_every < 1) throw InputError("--trace-every", "expected an integer >= 1");
  if (o.trace_field < 0) throw InputError("--trace-field", "expected an integer >= 1 (every K-th step; 0: no field records)");
  if (o.trace_field > 0 && o.trace_path.empty()) throw InputError("--trace-field", "needs --trace FILE");
  if (o.stall_window < 0) throw InputError("--stall-window", "expected a number of steps >= 0 (0: never stop early)");
  impl::io::refuse_output_that_is_an_input(o.trace_path, {o.scenario_path});
  impl::io::refuse_output_that_is_an_input(o.svg_path, {o.scenario_path});
  impl::io::refuse_output_that_is_another_output(o.svg_path, "--svg", o.trace_path, "--trace");
  const ValidScenario valid = resolve_scenario(o);
  const Scenario& s = valid.get();
  const std::string where = o.scenario_path.empty() ? "default scenario" : o.scenario_path;
  const cx::Engine engine = o.engine == "model" ? cx::Engine::model : cx::Engine::impl;
  // The process, and the larger of the map's cells (engine) and the reachability check's bit per
  // cell and queue, which is done before the map is allocated (measured: 16 bytes a cell of a
  // 3000 and a 5000 map, 1.0x of the peak).
  const double cells = static_cast<double>(s.map_size) * s.map_size;
  const double estimate = kProcessBytes + std::max(static_cast<double>(cx::estimated_bytes(engine, s)), cells / 8 + cells * 8);
  require_within(where, "a " + std::to_string(s.map_size) + " x " + std::to_string(s.map_size) + " map with " +
                            std::to_string(s.robots.size()) + " robots",
                 estimate, o.budgets.memory_bytes, "--memory-limit");
  const Reachability reach = reachability(s);
  if (reach.unreachable_free_cells > 0)
    fmt::print(stderr, "swarmcheck run: warning: {} of {} free cells cannot be reached by any robot (walled in); "
               "eP cannot reach 100 %\n", reach.unreachable_free_cells, free_cell_count(s));
  swarmcheck::exploration::ExplorationOptions options;
  options.threads = o.threads;
  const auto sim = cx::make_simulation(engine, valid, options);
  const int status = run_with(*sim, s, o, reach);
  report_memory(o.budgets, estimate);
  return status;
}

}  // namespace

void add_run_verb(CLI::App& app, int& exit_code) {
  auto opts = std::make_shared<ExplorationRunOptions>();
  CLI::App* cmd = app.add_subcommand(
      "run", "Run one exploration (the built-in thesis set-up when no file is given)");
  cmd->add_option("scenario", opts->scenario_path, "Scenario file (JSON); see README");
  cmd->add_option("--mode", opts->mode, "abstract | cosim (overrides the file)")
      ->check(CLI::IsMember({"abstract", "cosim"}));
  std::vector<std::string> rules;   // the rule sets' table (spec/exploration/rule_set.hpp)
  for (const auto& row : swarmcheck::exploration::kRuleSets) rules.emplace_back(row.name);
  cmd->add_option("--rule", opts->rule,
                  "The rule set (overrides the file)")
      ->check(CLI::IsMember(rules));
  add_robot_options(cmd, opts->robots);
  cmd->add_option("--seed", opts->seed, "The run's one seed (overrides the file)")->check(seed_validator());
  cmd->add_option("--steps", opts->steps, "Master steps at most (overrides max_steps)");
  cmd->add_option("--trace", opts->trace_path, "Write the JSON Lines trace to FILE");
  cmd->add_option("--trace-every", opts->trace_every, "Record every K-th step in the trace")
      ->capture_default_str();
  cmd->add_option("--trace-field", opts->trace_field,
                  "Also record the whole pheromone field and the visited set every K steps (trace format 2)");
  cmd->add_option("--svg", opts->svg_path, "Write a picture of the end of the run (coverage, pheromone, paths)");
  cmd->add_option("--stall-window", opts->stall_window,
                  "Stop as stalled after this many steps without a newly visited cell (0: never)")
      ->capture_default_str();
  add_budget_options(cmd, opts->budgets, true);
  add_threads_option(cmd, opts->threads, "Threads for the impl's planning, deposits and robots");
  cmd->add_option("--engine", opts->engine, "impl (the optimised library) | model (the reference)")
      ->check(CLI::IsMember({"impl", "model"}))
      ->capture_default_str();
  cmd->add_flag("--json", opts->json, "Print the summary as one JSON object");
  cmd->callback([opts, &exit_code] { exit_code = guarded([&] { return run(*opts); }); });
}

}  // namespace swarmcheck::cli
