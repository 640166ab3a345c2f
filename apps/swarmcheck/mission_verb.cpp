// `swarmcheck mission plan MISSION.json [--from STATE] [--planner exact|thesis] [--json]`
// `swarmcheck mission run MISSION.json [--trace FILE] [--json] [--body unicycle|kinematic]`
// The mission file is loaded and checked first (bad input: one message, status 2). plan prints
// the events in order, each robot's tasks and travel, the makespan and the total (status 1 when
// no marked state can be reached). run simulates the robots under the supervisor and reports
// whether the mission completed (status 0) or why not (status 1); --trace writes JSON Lines
// (TraceFile: temporary file + rename). The library does the work; the thesis baseline planner
// is reached through the harness (conformance/mission/engine).
#include "apps/swarmcheck/mission_verb.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <nlohmann/json.hpp>

#include "apps/swarmcheck/verb.hpp"
#include "spec/util/hana_json.hpp"
#include "conformance/mission/engine.hpp"
#include "swarmcheck/mission.hpp"
#include "swarmcheck/mission_report.hpp"
#include "impl/io/atomic_file.hpp"
#include "views/mission_svg.hpp"

namespace swarmcheck::cli {

namespace {

namespace sm = swarmcheck::mission;
using Json = nlohmann::ordered_json;

struct PlanOptions {
  std::string file;
  std::string from;
  std::string planner = "exact";
  bool json = false;
};

struct RunOptions {
  std::string file;
  std::string trace;
  std::string svg;
  std::string body = "unicycle";
  double dt = 0.05;
  double max_time = 3600.0;
  Budgets budgets;
  double speed = 0.5;
  std::uint64_t seed = 1;
  bool json = false;
};

std::string join(const std::vector<std::string>& xs) {
  std::string out;
  for (const auto& x : xs) out += (out.empty() ? "" : ", ") + x;
  return out;
}

int run_plan(const PlanOptions& o) {
  const sm::Mission m = sm::load_mission(o.file);
  const std::string from = o.from.empty() ? m.initial_state : o.from;
  if (std::find(m.fsm.states.begin(), m.fsm.states.end(), from) == m.fsm.states.end())
    throw InputError("--from", fmt::format("state \"{}\" is not in {}", from, m.fsm_name));
  const sm::PlanQuery q = sm::query_from(m, from);
  namespace engines = swarmcheck::conformance::mission;
  const sm::Plan p = engines::plan(m, q, engines::planner_named(o.planner));
  const auto seqs = sm::task_sequences(m, p.events);
  if (o.json) {
    fmt::print("{}\n", json_io::dump_text(sm::mission_plan_report(m, p, o.file, o.planner, from), 2));
  } else if (p.found) {
    fmt::print("plan ({} planner) from {} to {}: {} events\n", o.planner, from, p.final_state,
               p.events.size());
    fmt::print("  events: {}\n", join(p.events));
    for (std::size_t r = 0; r < m.robots.size(); ++r) {
      std::vector<std::string> names;
      for (const auto t : seqs[r]) names.push_back(m.tasks[t].name);
      fmt::print("  robot {}: {}  travel {:.3f} m\n", m.robots[r].name,
                 names.empty() ? std::string("(no task)") : join(names), p.cost.travel[r]);
    }
    fmt::print("  makespan {:.3f} m, total {:.3f} m\n", p.cost.makespan, p.cost.total);
  }
  if (!p.found) {
    if (!o.json) fmt::print("no marked state is reachable from {}\n", from);
    return 1;
  }
  return 0;
}

// Seconds robot `name` spent in `a` over the run.
double time_in(const sm::RunResult& r, const std::string& name, sm::Activity a) {
  double s = 0.0;
  for (const auto& i : r.intervals)
    if (i.robot == name && i.activity == a) s += i.to_s - i.from_s;
  return s;
}

// What `mission run` needs at its peak: the process, the world's grids (a byte a cell for the
// world and each robot's map), and the paths the picture keeps, two doubles a point in vectors
// that double as they grow. A path keeps a point a step, but only when the robot has moved 2 cm
// since the last: at most min(steps, fastest speed x time / 2 cm) points a robot (the unicycle
// body's servos saturate at r K = 0.17 m/s). Before, every step was counted: 1e9 steps of a run
// that moves a few metres were refused at 32 GB.
double mission_run_peak(const swarmcheck::mission::Mission& m, const RunOptions& o, double steps) {
  const double robots = static_cast<double>(m.robots.size());
  const double fastest = o.body == "kinematic" ? std::abs(o.speed) : 0.2;
  const double points = std::min(steps + 1.0, fastest * o.max_time / 0.02 + 2.0);
  const double world = m.world ? static_cast<double>(m.world->rows * m.world->cols) * (robots + 2.0) : 0.0;
  return kProcessBytes + world + robots * 16.0 * grown_elements(points);
}

int run_run(const RunOptions& o) {
  const std::vector<std::string> inputs = sm::mission_input_files(o.file);   // the mission and its .fsm
  impl::io::refuse_output_that_is_an_input(o.trace, inputs);
  impl::io::refuse_output_that_is_an_input(o.svg, inputs);
  impl::io::refuse_output_that_is_another_output(o.svg, "--svg", o.trace, "--trace");
  for (const std::string& out : {o.trace, o.svg})   // before the run, not after the trace is written
    if (!out.empty()) impl::io::check_output_path(out);
  const sm::Mission m = sm::load_mission(o.file);
  if (!(o.dt > 0) || !std::isfinite(o.dt)) throw InputError("--dt", "expected a step in seconds > 0");
  if (!(o.max_time > 0) || !std::isfinite(o.max_time)) throw InputError("--max-time", "expected a time in seconds > 0");
  // Budgets, before anything runs: a step record per dt with each robot's position in the trace
  // (about 40 bytes a robot), and the paths the picture keeps (16 bytes a robot a step).
  const double steps = o.max_time / o.dt + 1.0;
  const double robots = static_cast<double>(m.robots.size());
  const std::string run_size = "--max-time " + fmt::format("{:g}", o.max_time) + " s at --dt " + fmt::format("{:g}", o.dt) +
                               " s (" + fmt::format("{:.3g}", steps) + " steps)";
  if (!o.trace.empty())
    require_within("--trace " + o.trace, "the trace of " + run_size, steps * (60.0 + 40.0 * robots),
                   o.budgets.trace_bytes, "--max-trace-bytes");
  const double estimate = mission_run_peak(m, o, steps);
  require_within(o.file, "the run's paths over " + run_size, estimate, o.budgets.memory_bytes, "--memory-limit");
  sm::RunOptions ro;
  if (o.body == "kinematic") ro.body = sm::BodyModel::kinematic;
  ro.dt_s = o.dt;
  ro.max_time_s = o.max_time;
  ro.speed_m_per_s = o.speed;
  ro.seed = o.seed;
  std::unique_ptr<sm::TraceFile> trace;
  if (!o.trace.empty()) trace = std::make_unique<sm::TraceFile>(o.trace, m, ro);
  views::MissionPathRecorder paths(m.robots.size(), trace.get());
  const sm::RunResult r = sm::run_mission(m, ro, &paths);
  // Both outputs written, then both committed: a picture that cannot be written leaves the old trace.
  std::optional<impl::io::AtomicFile> svg;
  if (!o.svg.empty()) {
    svg.emplace(o.svg);
    svg->stream() << views::mission_svg({&m, paths.paths(), "mission " + o.file,
                                         (r.completed ? "mission complete" : r.reason) + fmt::format(" at t={:.2f} s in state {}", r.time_s, r.final_state)});
  }
  if (trace) trace->commit();
  if (svg) svg->commit();
  report_memory(o.budgets, estimate);
  if (o.json) {
    fmt::print("{}\n", json_io::dump_text(sm::mission_run_report(m, r, o.file, o.body), 2));
  } else {
    for (const auto& e : r.events)
      fmt::print("  t={:8.2f} s  {:<6} -> {}\n", e.time_s, e.event, e.state_after);
    fmt::print("{} at t={:.2f} s in state {}\n", r.completed ? "mission complete" : r.reason,
               r.time_s, r.final_state);
    for (std::size_t k = 0; k < m.robots.size(); ++k) {
      const std::string& n = m.robots[k].name;
      fmt::print("  robot {}: travelled {:.3f} m; busy {:.2f} s, waiting for the supervisor {:.2f} s, "
                 "for a task {:.2f} s, for a robot {:.2f} s\n", n, r.travel[k],
                 time_in(r, n, sm::Activity::busy),
                 time_in(r, n, sm::Activity::waiting_for_supervisor),
                 time_in(r, n, sm::Activity::waiting_for_task),
                 time_in(r, n, sm::Activity::waiting_for_robot));
    }
    fmt::print("  planned makespan {:.3f} m\n", r.makespan_planned);
  }
  return r.completed ? 0 : 1;
}

}  // namespace

void add_mission_verb(CLI::App& app, int& exit_code) {
  auto* mission = app.add_subcommand("mission", "plan or run an FSM-supervised multi-robot mission");
  mission->require_subcommand(1);

  auto po = std::make_shared<PlanOptions>();
  auto* plan = mission->add_subcommand(
      "plan", "the events of least makespan, then least total travel, to a marked state");
  plan->add_option("mission", po->file, "mission file (JSON)")->required();
  plan->add_option("--from", po->from, "plan from this FSM state (robots at their starts)");
  plan->add_option("--planner", po->planner, "exact (default) or thesis (the baseline)")
      ->check(CLI::IsMember({"exact", "thesis"}));
  plan->add_flag("--json", po->json, "print JSON");
  plan->callback([po, &exit_code] { exit_code = guarded([&] { return run_plan(*po); }); });

  auto ro = std::make_shared<RunOptions>();
  auto* run = mission->add_subcommand("run", "run the mission in simulation under the supervisor");
  run->add_option("mission", ro->file, "mission file (JSON)")->required();
  run->add_option("--trace", ro->trace, "write the run as JSON Lines to this file");
  run->add_option("--svg", ro->svg, "write a picture of the run (regions, tasks, paths) to this file");
  run->add_option("--body", ro->body, "unicycle (controller + body, default) or kinematic")
      ->check(CLI::IsMember({"unicycle", "kinematic"}));
  run->add_option("--dt", ro->dt, "simulation step, s (default 0.05)")
      ->check(CLI::Range(1e-4, 1.0));
  run->add_option("--max-time", ro->max_time, "time limit, s (default 3600)")
      ->check(CLI::Range(0.0, 1e7));
  add_budget_options(run, ro->budgets, true);
  run->add_option("--seed", ro->seed, "seed of the range sensor's noise (default 1)")->check(seed_validator());
  run->add_option("--speed", ro->speed, "kinematic body speed, m/s (default 0.5)")
      ->check(CLI::Range(1e-3, 100.0));
  run->add_flag("--json", ro->json, "print a JSON summary");
  run->callback([ro, &exit_code] { exit_code = guarded([&] { return run_run(*ro); }); });
}

}  // namespace swarmcheck::cli
