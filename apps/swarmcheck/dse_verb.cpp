// swarmcheck dse: design-space exploration on an INTO-CPS DSE configuration, on threads here or
// on Open MPI ranks; results, report and journal in one folder.
#include "apps/swarmcheck/dse_verb.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <memory>
#include <numeric>
#include <thread>

#include "apps/swarmcheck/mpi_pool.hpp"
#include "apps/swarmcheck/robot_options.hpp"
#include "apps/swarmcheck/stop_request.hpp"
#include "apps/swarmcheck/verb.hpp"
#include "impl/dse/format.hpp"
#include "impl/dse/report_html.hpp"
#include "impl/dse/report_svg.hpp"
#include "impl/dse/results_io.hpp"
#include "impl/dse/sweep.hpp"
#include "impl/io/atomic_file.hpp"
#include "spec/exploration/scenario.hpp"
#include "spec/util/json_text.hpp"

namespace swarmcheck::cli {
namespace {

using namespace swarmcheck::dse;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct DseArgs {
  std::string config_path;
  std::string scenario_path;   // empty: the built-in default
  RobotChoiceOptions robots;   // --controller, --body, --preset over the base scenario
  std::string out_dir = "dse-out";
  int32_t threads = 0;         // 0: every core
  bool json = false;
  Budgets budgets;             // --memory-limit
};

// SIGINT / SIGTERM: finish the points in flight, keep them in the journal, exit 130 / 143. A second
// one ends the process at once; the journal stays consistent.
constexpr const char* kDseStopMessage =
    "\nswarmcheck dse: interrupted: finishing the points in flight (Ctrl-C again to stop now)\n";

// A progress bar with ETA on stderr, only when stderr is a terminal.
class ProgressBar {
 public:
  explicit ProgressBar(bool genetic) : enabled_(::isatty(2) == 1), genetic_(genetic), start_(Clock::now()) {}
  void update(const SweepProgress& p) {
    if (!enabled_) return;
    const auto now = Clock::now();
    if (p.done < p.total && now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double rate = p.computed > 0 ? static_cast<double>(p.computed) / elapsed : 0;
    const std::size_t width = 30;
    const std::size_t filled = p.total ? width * p.done / p.total : width;
    std::string eta = "--:--";
    if (rate > 0) {
      const auto s = static_cast<long long>(static_cast<double>(p.total - p.done) / rate);
      eta = fmt::format("{}:{:02d}", s / 60, s % 60);
    }
    fmt::print(stderr, "\r{}[{}{}] {}/{} points  {:.1f} points/s  ETA {}   ", genetic_ ? fmt::format("gen {} ", p.generation) : "",
               std::string(filled, '#'), std::string(width - filled, '.'), p.done, p.total, rate, eta);
  }
  void finish() {
    if (enabled_) fmt::print(stderr, "\r{:90}\r", "");
  }

 private:
  bool enabled_, genetic_;
  Clock::time_point start_, last_{};
};

// Design points on the other MPI ranks: a genome out, the point's runs (JSON) back.
class MpiExecutor : public Executor {
 public:
  explicit MpiExecutor(const std::atomic<bool>& stop) : stop_(stop) {}
  void evaluate(const std::vector<Genome>& batch, const std::function<void(std::size_t, PointRuns)>& done) override {
    std::vector<std::string> tasks;
    for (const Genome& g : batch) tasks.push_back(json_io::Json(g).dump());
    mpi::distribute(tasks, [&](std::size_t i, std::string reply) { done(i, point_runs_from_json(json_io::parse_json_text(reply, "MPI reply"))); },
                    [this](std::size_t) { return stop_.load(); });
  }

 private:
  const std::atomic<bool>& stop_;
};

// The output folder's files (journal.jsonl besides: written as the sweep goes).
constexpr std::array<const char*, 4> kOutputFiles = {"results.csv", "results.json", "report.svg", "report.html"};

// Every content made before the first file is written, so that nothing is left half-written.
// (Paths in results.json are the user's bytes: dump_text writes U+FFFD for any that are not UTF-8.)
void write_outputs(const std::string& dir, const DesignSpace& space, const DseResults& r, const ResultsContext& ctx) {
  const fs::path d(dir);
  const std::array<std::string, kOutputFiles.size()> contents = {
      results_csv(space, r), json_io::dump_text(results_json(space, r, ctx), 2) + "\n", pareto_svg(space, r),
      report_html(space, r, ctx)};
  for (std::size_t k = 0; k < kOutputFiles.size(); ++k) io::write_file_atomically((d / kOutputFiles[k]).string(), contents[k]);
}

// Before the sweep: each output is a file (or nothing yet), and none is an input, through a link
// or not (a link in the folder to the scenario would have had the results written over it).
void check_output_folder(const DseArgs& a) {
  const std::vector<std::string> inputs = {a.config_path, a.scenario_path};
  std::vector<const char*> names(kOutputFiles.begin(), kOutputFiles.end());
  names.push_back("journal.jsonl");
  for (const char* name : names) {
    const std::string p = (fs::path(a.out_dir) / name).string();
    io::refuse_output_that_is_an_input(p, inputs);
    io::check_output_path(p);
  }
}

// The ranking's first rows as a table that fits a screen.
void print_table(const DesignSpace& space, const DseResults& r) {
  const DseConfig& c = space.config();
  // The parameters that vary (all when none does), objectives to 6 significant digits.
  std::vector<std::size_t> shown_params;
  for (std::size_t k = 0; k < c.parameters.size(); ++k)
    if (c.parameters[k].values.size() > 1) shown_params.push_back(k);
  if (shown_params.empty())
    for (std::size_t k = 0; k < c.parameters.size(); ++k) shown_params.push_back(k);
  std::vector<std::vector<std::string>> rows{{"rank", "point"}};
  for (const std::size_t k : shown_params) rows[0].push_back(plain_name(c.parameters[k].name));
  for (const Objective& o : c.objectives) rows[0].push_back(o.name);
  rows[0].push_back("status");
  std::vector<std::size_t> order(r.points.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const auto key = [&](std::size_t i) { return r.points[i].rank > 0 ? r.points[i].rank : INT32_MAX; };
    return key(a) < key(b);
  });
  const std::size_t shown = std::min<std::size_t>(order.size(), 15);
  for (std::size_t n = 0; n < shown; ++n) {
    const PointResult& p = r.points[order[n]];
    std::vector<std::string> row{p.rank > 0 ? std::to_string(p.rank) : "-", std::to_string(order[n] + 1)};
    for (const std::size_t k : shown_params) row.push_back(parameter_value_text(space, p.genome, k));
    for (std::size_t k = 0; k < c.objectives.size(); ++k) {
      const bool has = k < p.objectives.size() && p.objectives[k].present;
      std::string cell = has ? fmt::format("{:.6g}", p.objectives[k].mean) : "";
      if (has && p.objectives[k].ci95) cell += " ±" + fmt::format("{:.3g}", *p.objectives[k].ci95);
      row.push_back(cell);
    }
    row.push_back(p.status);
    rows.push_back(std::move(row));
  }
  std::vector<std::size_t> width(rows[0].size(), 0);
  for (const auto& row : rows)
    for (std::size_t k = 0; k < row.size(); ++k) width[k] = std::max(width[k], row[k].size());
  for (const auto& row : rows) {
    std::string line = " ";
    for (std::size_t k = 0; k < row.size(); ++k) line += " " + row[k] + std::string(width[k] - row[k].size(), ' ');
    while (!line.empty() && line.back() == ' ') line.pop_back();
    fmt::print("{}\n", line);
  }
  if (order.size() > shown) fmt::print("  ... {} more points in results.csv\n", order.size() - shown);
}

void print_summary(const DseArgs& a, const DesignSpace& space, const DseResults& r, const SweepOutcome& o,
                   double seconds, const std::string& workers) {
  const DseConfig& c = space.config();
  fmt::print("swarmcheck dse: {} on {}: {}\n", a.config_path, a.scenario_path.empty() ? "the default scenario" : a.scenario_path,
             c.algorithm == Algorithm::genetic
                 ? fmt::format("genetic search, {} generations, {} of {} points evaluated", r.generations, r.points.size(), space.size())
                 : fmt::format("exhaustive, {} points", r.points.size()));
  fmt::print("ran {} points ({} runs) in {:.2f} s on {}: {:.1f} runs/s; {} points from the journal\n", o.computed, o.runs,
             seconds, workers, seconds > 0 ? static_cast<double>(o.runs) / seconds : 0.0, o.from_journal);
  print_table(space, r);
  fmt::print("Pareto front ({} point{}): {}\n", r.front.size(), r.front.size() == 1 ? "" : "s", front_text(space, r, 6));
  const fs::path d(a.out_dir);
  fmt::print("wrote {}, {}, {}, {}\n", (d / "results.csv").string(), (d / "results.json").string(),
             (d / "report.html").string(), (d / "report.svg").string());
}

// Everything that can be wrong with the input, before any file or folder is touched.
struct Plan {
  DseConfig config;
  exploration::Scenario base;
};

Plan load_plan(const DseArgs& a) {
  DseConfig config = load_dse_config(a.config_path);
  exploration::ScenarioOverrides over;
  apply_robot_choices(a.robots, "", over);
  exploration::ValidScenario base = a.scenario_path.empty() ? exploration::ValidScenario(exploration::default_scenario())
                                                            : exploration::load_valid_scenario(a.scenario_path);
  Plan p{std::move(config), exploration::with_overrides(std::move(base), over).get()};
  if (a.threads < 0) throw InputError("--threads", "expected an integer >= 0 (0: every core)");
  return p;
}

int run_rank0(const DseArgs& a, const DesignSpace& space, Executor& executor, const std::string& workers,
              const StopRequest& stop) {
  std::error_code ec;
  fs::create_directories(a.out_dir, ec);
  if (ec) throw InputError(a.out_dir, "cannot create the output folder: " + ec.message());
  check_output_folder(a);
  ProgressBar bar(space.config().algorithm == Algorithm::genetic);
  SweepOptions options{(fs::path(a.out_dir) / "journal.jsonl").string(), &stop.flag(),
                       [&bar](const SweepProgress& p) { bar.update(p); }};
  const auto start = Clock::now();
  const SweepOutcome outcome = run_sweep(space, executor, options);
  bar.finish();
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (outcome.interrupted) {
    fmt::print(stderr, "swarmcheck dse: interrupted after {} new points ({} runs); they are in {}. Run the same command "
                       "again to finish the sweep.\n", outcome.computed, outcome.runs, options.journal_path);
    return stop.exit_status();
  }
  DseResults results = rank_outcomes(space, outcome.points);
  results.generations = outcome.generations;
  const ResultsContext ctx{a.config_path, a.scenario_path.empty() ? "default scenario" : a.scenario_path};
  write_outputs(a.out_dir, space, results, ctx);
  if (a.json)
    fmt::print("{}\n", json_io::dump_text(results_json(space, results, ctx)));
  else
    print_summary(a, space, results, outcome, seconds, workers);
  return 0;
}

int dse_threads(const DseArgs& a) {
  const Plan plan = load_plan(a);
  const DesignSpace space(plan.config, plan.base);
  const int32_t threads = a.threads > 0 ? a.threads : static_cast<int32_t>(std::max(1u, std::thread::hardware_concurrency()));
  // Points in memory at once: one a thread, no more threads than cores run (TBB), no more than there are points.
  const auto points_at_once = static_cast<int32_t>(std::min<uint64_t>(
      {static_cast<uint64_t>(threads), std::max(1u, std::thread::hardware_concurrency()), std::max<uint64_t>(1, space.size())}));
  const double estimate = check_design_space(space, a.budgets.memory_bytes, points_at_once);
  const StopRequest stop(kDseStopMessage);
  ThreadExecutor executor(space, needed_columns(plan.config), a.threads, &stop.flag());
  const int status = run_rank0(a, space, executor, fmt::format("{} thread{}", threads, threads == 1 ? "" : "s"), stop);
  report_memory(a.budgets, kProcessBytes + estimate);
  return status;
}

// Under mpirun: every rank reads and checks the input (so every rank agrees on the points);
// rank 0 runs the sweep, the others evaluate the points it sends.
int dse_mpi(const DseArgs& a) {
  mpi::Session session;
  if (session.rank() != 0) {
    std::signal(SIGINT, SIG_IGN);   // rank 0 decides when to stop
    try {
      const Plan plan = load_plan(a);
      const DesignSpace space(plan.config, plan.base);
      check_design_space(space, a.budgets.memory_bytes);   // one point at a time on each rank
      const std::vector<Column> columns = needed_columns(plan.config);
      mpi::serve([&](const std::string& task) {
        const Genome g = json_io::parse_json_text(task, "MPI task").get<Genome>();
        return to_json(evaluate_point(space, g, columns)).dump();
      });
    } catch (const InputError&) {
      return 2;   // rank 0 reports it
    }
    return 0;
  }
  const int status = guarded([&] {
    const Plan plan = load_plan(a);
    const DesignSpace space(plan.config, plan.base);
    check_design_space(space, a.budgets.memory_bytes);
    const StopRequest stop(kDseStopMessage);
    MpiExecutor executor(stop.flag());
    const int rc = run_rank0(a, space, executor, fmt::format("{} MPI ranks ({} computing)", session.size(), session.size() - 1), stop);
    mpi::release_workers();
    return rc;
  });
  if (status == 2 || status == 3) {
    std::fflush(stderr);
    mpi::Session::abort(status);   // workers may be waiting for tasks that will never come
  }
  return status;
}

int dse(const DseArgs& a) {
  const mpi::Launch launch = mpi::launch_from_environment();
  if (launch.size > 1) {
    if (!mpi::compiled_in()) {
      if (launch.rank == 0) throw InputError("mpirun", mpi::missing_mpi_message());
      return 2;
    }
    return dse_mpi(a);
  }
  return dse_threads(a);
}

}  // namespace

void add_dse_verb(CLI::App& app, int& exit_code) {
  auto a = std::make_shared<DseArgs>();
  CLI::App* cmd = app.add_subcommand(
      "dse", "Design-space exploration on an INTO-CPS DSE configuration (.dse.json): sweep, rank, report");
  cmd->add_option("config", a->config_path, "The DSE configuration (INTO-CPS format; see README)")->required();
  cmd->add_option("--scenario", a->scenario_path, "The base scenario the parameters change (default: the built-in one)");
  add_robot_options(cmd, a->robots);
  cmd->add_option("-o,--out", a->out_dir, "Folder for results.csv, results.json, report.html, report.svg, journal.jsonl")
      ->capture_default_str();
  add_threads_option(cmd, a->threads, "Design points in parallel");
  add_budget_options(cmd, a->budgets, false);
  cmd->add_flag("--json", a->json, "Print the results object (results.json) instead of the summary");
  cmd->callback([a, &exit_code] {
    exit_code = guarded([&] { return dse(*a); });
  });
}

}  // namespace swarmcheck::cli
