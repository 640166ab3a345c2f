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
  void update(const StepRecord& r, int64_t max_steps) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    fmt::print(stderr, "\rstep {:>9} / {}  eP {:6.2f} %  planning steps {}   ", r.step, max_steps,
               r.eP, r.planning_steps);
  }
  void finish() {
    if (enabled_) fmt::print(stderr, "\r{:80}\r", "");
  }

 private:
  bool enabled_;
  std::chrono::steady_clock::time_point last_;
};

void print_summary(const Scenario& s, const RunOptions& o, const StepRecord& r,
                   std::optional<int64_t> completion) {
  if (o.json) {
    json_io::Json j = json_io::Json::object();
    j["completed"] = completion.has_value();
    j["completion_step"] = completion ? json_io::Json(*completion) : json_io::Json(nullptr);
    j["steps"] = r.step;
    j["planning_steps"] = r.planning_steps;
    j["eP"] = r.eP;
    j["sTime"] = r.sTime;
    j["visited"] = r.visited;
    j["free_cells"] = r.free_cells;
    j["rule"] = json_io::enum_to_string(s.rule);
    j["mode"] = json_io::enum_to_string(s.mode);
    j["seed"] = s.seed;
    j["map_size"] = s.map_size;
    j["robots"] = s.robots.size();
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
               *completion, r.sTime, r.eP, r.visited, r.free_cells, r.planning_steps);
  else
    fmt::print("not complete after {} steps (max_steps): eP {:.2f} %, {} / {} free cells "
               "visited, {} planning steps\n",
               r.step, r.eP, r.visited, r.free_cells, r.planning_steps);
}

int run(const RunOptions& o) {
  if (o.trace_every < 1) throw InputError("--trace-every", "expected an integer >= 1");
  const Scenario s = resolve_scenario(o);
  std::unique_ptr<AtomicOutputFile> trace;
  if (!o.trace_path.empty()) {
    trace = std::make_unique<AtomicOutputFile>(o.trace_path);
    trace->stream() << trace_header(s).dump() << '\n';
  }
  model::ExplorationModel m(s);
  Progress progress;
  StepRecord r = m.record();
  if (trace) trace->stream() << trace_line(r) << '\n';
  while (!m.done()) {
    m.step();
    const bool last = m.done();
    if (trace && (m.steps() % o.trace_every == 0 || last)) {
      r = m.record();
      trace->stream() << trace_line(r) << '\n';
    }
    if (m.steps() % 256 == 0) progress.update(m.record(), s.max_steps);
  }
  progress.finish();
  r = m.record();
  if (trace) trace->commit();
  print_summary(s, o, r, m.environment().completion_step());
  return 0;
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
  cmd->add_flag("--json", opts->json, "Print the summary as one JSON object");
  cmd->callback([opts, &exit_code] { exit_code = guarded([&] { return run(*opts); }); });
}

}  // namespace swarmcheck::cli
