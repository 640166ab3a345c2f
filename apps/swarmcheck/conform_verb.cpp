// swarmcheck conform / replay: the differential harness on the command line.
#include "apps/swarmcheck/conform_verb.hpp"

#include <fcntl.h>
#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>

#include "apps/swarmcheck/conform_fmu.hpp"
#include "apps/swarmcheck/conform_systems.hpp"
#include "apps/swarmcheck/mpi_pool.hpp"
#include "apps/swarmcheck/verb.hpp"
#include "conformance/exploration/conform.hpp"
#include "conformance/exploration/trace_io.hpp"
#include "proofs/obligations/handshake_trace.hpp"
#include "spec/exploration/rng.hpp"
#include "spec/exploration/scenario.hpp"
#include "spec/util/hana_json.hpp"
#include "spec/util/json_text.hpp"
#include "spec/util/input_file.hpp"

namespace swarmcheck::cli {
namespace {

using namespace swarmcheck::conformance::exploration;
using json_io::Json;
namespace fs = std::filesystem;

struct ConformArgs {
  ConformOptions options;
  double case_time_limit_s = 60;   // --case-time-limit
  std::string system = "all";   // all | exploration | automata | missions
  bool cases_given = false;     // --cases on the command line: every system's budget
  bool json = false;
  bool stats = false;
  ConformFmuArgs fmu;           // --fmu FILE ...: the user's FMUs instead of the library
};

Json coverage_json(const Coverage& c) {
  return Json{{"cases_by_family", c.cases_by_family},
              {"cases_by_rule_mode", c.cases_by_rule_mode},
              {"grouped_cases", c.grouped_cases},
              {"longest_run_steps", c.longest_run_steps},
              {"max_cell_age", c.max_cell_age},
              {"cases_age_past_2_12", c.cases_age_past_2_12},
              {"cases_steps_past_2_15", c.cases_steps_past_2_15},
              {"negative_zero_starts", c.negative_zero_starts},
              {"off_centre_starts", c.off_centre_starts},
              {"heading_near_pi_cases", c.heading_near_pi_cases},
              {"completed_cases", c.completed_cases},
              {"grouped_steps_rows_kept", c.grouped_steps_rows_kept},
              {"grouped_steps_one_row_changed", c.grouped_steps_one_row_changed},
              {"grouped_steps_rows_exchanged", c.grouped_steps_rows_exchanged}};
}

void print_coverage(const Coverage& c) {
  fmt::print("coverage of the cases run before any divergence:\n");
  for (const auto& [family, n] : c.cases_by_family) fmt::print("  family {:<26} {:>6} cases\n", family, n);
  for (const auto& [rm, n] : c.cases_by_rule_mode) fmt::print("  {:<33} {:>6} cases\n", rm, n);
  fmt::print("  grouped (parallel) planning      {:>6} cases\n", c.grouped_cases);
  fmt::print("  longest run                      {:>6} steps\n", c.longest_run_steps);
  fmt::print("  largest cell age evaluated       {:>6} ticks\n", c.max_cell_age);
  fmt::print("  cases with ages past 2^12        {:>6}\n", c.cases_age_past_2_12);
  fmt::print("  cases with ticks past 2^15       {:>6}\n", c.cases_steps_past_2_15);
  fmt::print("  robots starting at -0.0          {:>6} cases\n", c.negative_zero_starts);
  fmt::print("  robots starting off centre       {:>6} cases\n", c.off_centre_starts);
  fmt::print("  headings within 0.05 of +-pi     {:>6} cases\n", c.heading_near_pi_cases);
  fmt::print("  completed (completion compared)  {:>6} cases\n", c.completed_cases);
  fmt::print("  parallel steps, rows all kept    {:>6}\n", c.grouped_steps_rows_kept);
  fmt::print("  parallel steps, one row changed  {:>6}\n", c.grouped_steps_one_row_changed);
  fmt::print("  parallel steps, rows exchanged   {:>6}\n", c.grouped_steps_rows_exchanged);
}

Json case_summary(const ExplorationCase& c) {
  const auto& s = c.scenario;
  return Json{{"map_size", s.map_size}, {"robots", s.robots.size()}, {"obstacles", s.obstacles.size()},
              {"rule", json_io::enum_to_string(s.rule)}, {"mode", json_io::enum_to_string(s.mode)},
              {"grouped", c.grouped}};
}

// Under mpirun the campaign is cut into chunks of kChunkCases cases; chunk k is exactly the
// one-process campaign `conform --cases n_k --seed chunk_seed(S, k)` (chunk 0 keeps S), so any
// divergence reproduces without MPI. Ranks take chunks as they free up; rank 0 reports the
// divergence of the lowest chunk (chunks above a known divergence are not started), re-running
// that chunk itself so that it alone writes the counterexample. The verdict does not depend on
// the number of ranks.
constexpr int kChunkCases = 50;

int report(const ConformArgs& a, const ConformReport& r, const Json& ranks, Json* json_out);

uint64_t chunk_seed(uint64_t seed, std::size_t chunk) {
  return chunk == 0 ? seed : swarmcheck::exploration::splitmix64(seed ^ swarmcheck::exploration::splitmix64(chunk));
}

int conform_on_ranks(const ConformArgs& a, Json* json_out) {
  if (a.options.cases < 1) throw InputError("--cases", "expected an integer >= 1");   // every rank, before any waits
  if (a.options.max_steps < 1) throw InputError("--max-steps", "expected an integer >= 1");
  mpi::Session session;
  std::vector<std::string> tasks;
  for (int start = 0; start < a.options.cases; start += kChunkCases) {
    const std::size_t k = tasks.size();
    tasks.push_back(Json{{"cases", std::min(kChunkCases, a.options.cases - start)}, {"seed", chunk_seed(a.options.seed, k)}}.dump());
  }
  if (session.rank() != 0) {
    const fs::path scratch = fs::temp_directory_path() / ("swarmcheck-conform-rank" + std::to_string(session.rank()) + "-" + std::to_string(::getpid()));
    mpi::serve([&](const std::string& task) {
      ConformOptions o = a.options;
      const Json t = json_io::parse_json_text(task, "MPI task");
      o.cases = t.at("cases").get<int>();
      o.seed = t.at("seed").get<uint64_t>();
      o.out_dir = scratch.string();   // rank 0 owns the files: it re-runs a diverging chunk itself
      const ConformReport r = run_conform(o);
      return Json{{"cases_run", r.cases_run}, {"agree", !r.counterexample.has_value()}}.dump();
    });
    std::error_code ignored;
    fs::remove_all(scratch, ignored);
    return 0;
  }
  int cases_run = 0;
  std::size_t lowest = tasks.size();   // the lowest diverging chunk
  mpi::distribute(tasks, [&](std::size_t k, std::string reply) {
    const Json r = json_io::parse_json_text(reply, "MPI reply");
    cases_run += r.at("cases_run").get<int>();
    if (!r.at("agree").get<bool>()) lowest = std::min(lowest, k);
  }, [&](std::size_t k) { return k > lowest; });
  mpi::release_workers();
  Json ranks{{"ranks", session.size()}, {"chunks", tasks.size()}, {"chunk_cases", kChunkCases}};
  ConformReport r;
  if (lowest < tasks.size()) {
    ConformArgs chunk = a;
    const Json t = json_io::parse_json_text(tasks[lowest], "MPI task");
    chunk.options.cases = t.at("cases").get<int>();
    chunk.options.seed = t.at("seed").get<uint64_t>();
    r = run_conform(chunk.options);
    ranks["chunk"] = lowest;
    ranks["text"] = fmt::format("chunk {} of {} on {} MPI ranks; without MPI: swarmcheck conform --cases {} --seed {}", lowest,
                                tasks.size(), session.size(), chunk.options.cases, chunk.options.seed);
    r.cases_run = cases_run;
    return report(a, r, ranks, json_out);
  }
  r.cases_run = cases_run;
  ranks["text"] = fmt::format("; {} MPI ranks, {} chunks of up to {} cases with derived seeds", session.size(), tasks.size(), kChunkCases);
  return report(a, r, ranks, json_out);
}

// Prints the campaign's report; `ranks` (under mpirun) adds how the campaign was split.
int report(const ConformArgs& a, const ConformReport& r, const Json& ranks, Json* json_out) {
  const auto& cx = r.counterexample;
  if (a.json) {
    Json j{{"agree", !cx.has_value()}, {"cases_run", r.cases_run}, {"seed", a.options.seed}};
    if (a.stats) j["coverage"] = coverage_json(r.coverage);
    if (!ranks.is_null()) {
      j["mpi"] = ranks;
      j["mpi"].erase("text");
    }
    if (cx)
      j["counterexample"] = {{"trace", cx->trace_path}, {"step", cx->divergence.step},
                             {"path", cx->divergence.path}, {"text", cx->divergence.describe()},
                             {"shrinks", cx->shrinks}, {"case", case_summary(cx->minimal)}};
    if (cx && !cx->divergence.abnormal_end.empty()) j["counterexample"]["abnormal_end"] = cx->divergence.abnormal_end;
    if (json_out)
      *json_out = j;
    else
      fmt::print("{}\n", j.dump());
  } else if (!cx) {
    fmt::print("conform: impl and model agree bit for bit on {} cases (seed {}{})\n", r.cases_run, a.options.seed,
               ranks.is_null() ? "" : ranks.value("text", ""));
    if (a.stats) print_coverage(r.coverage);
  } else {
    const auto& s = cx->minimal.scenario;
    fmt::print("conform: DIVERGENCE after {} cases (seed {}); shrunk {} times to map {}, {} robots, "
               "{} obstacles, rule {}, mode {}\n  {}\n  trace: {}\n  replay: swarmcheck replay {}\n",
               r.cases_run, a.options.seed, cx->shrinks, s.map_size, s.robots.size(), s.obstacles.size(),
               json_io::enum_to_string(s.rule), json_io::enum_to_string(s.mode), cx->divergence.describe(),
               cx->trace_path, cx->trace_path);
    if (ranks.is_null())
      fmt::print("  reproduce: swarmcheck conform --seed {} --cases {} --max-steps {}\n", a.options.seed,
                 a.options.cases, a.options.max_steps);
    else
      fmt::print("  {}\n", ranks.value("text", ""));
    if (a.stats) print_coverage(r.coverage);
  }
  return cx ? 1 : 0;
}

// The exploration campaign: split across MPI ranks under mpirun, else on this process.
int conform_exploration(ConformArgs a, const mpi::Launch& launch, Json* json_out) {
  if (launch.size > 1) {
    if (!mpi::compiled_in()) {
      if (launch.rank == 0) throw InputError("mpirun", mpi::missing_mpi_message());
      return 2;
    }
    return conform_on_ranks(a, json_out);
  }
  const bool tty = ::isatty(2) == 1 && !a.json;
  if (tty)
    a.options.on_case = [](int done, int asked) {
      if (done % 10 == 0 || done == asked) fmt::print(stderr, "\rexploration case {} / {}", done, asked);
    };
  const ConformReport r = run_conform(a.options);
  if (tty) fmt::print(stderr, "\r{:50}\r", "");
  return report(a, r, Json(), json_out);
}

// --out, checked before the campaign (a counterexample may come after an hour of cases): an
// existing folder, or one that can be made. Alone, the check writes: a file is made in the folder
// and removed, or the folder is made and removed (nothing is left behind when every case
// agrees). Under mpirun every rank checks the same way, reading only (ranks on one machine would
// race on the probe), so that all of them stop together or none does.
std::optional<InputError> counterexample_folder_problem(const std::string& dir, bool probe) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path d(dir);
  if (fs::exists(d, ec)) {
    if (!fs::is_directory(d, ec)) return InputError(dir, "is not a folder (--out names the folder for counterexample traces)");
    if (!probe) return std::nullopt;
    const fs::path file = d / (".swarmcheck-probe-" + std::to_string(::getpid()));
    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
    if (fd < 0) return InputError(dir, "cannot write counterexample traces in this folder: " + std::string(std::strerror(errno)));
    ::close(fd);
    fs::remove(file, ec);
    return std::nullopt;
  }
  fs::path first_made = d;   // the outermost folder that does not exist yet
  for (fs::path p = d.parent_path(); !p.empty() && !fs::exists(p, ec); p = p.parent_path()) first_made = p;
  if (!probe) {
    const fs::path parent = first_made.parent_path().empty() ? fs::path(".") : first_made.parent_path();
    if (!fs::is_directory(parent, ec) || ::access(parent.c_str(), W_OK) != 0)
      return InputError(dir, "cannot make the folder for counterexample traces in " + parent.string());
    return std::nullopt;
  }
  if (!fs::create_directories(d, ec) || ec)
    return InputError(dir, "cannot make the folder for counterexample traces: " + (ec ? ec.message() : std::string("unknown error")));
  fs::remove_all(first_made, ec);   // made only to know it can be; made again if a counterexample comes
  return std::nullopt;
}

// Every system asked for, each with its own campaign from the one seed; under mpirun only the
// exploration campaign is split, rank 0 runs the others. Exit 1 if any finds a difference.
int conform(ConformArgs a) {
  if (a.options.cases < 1) throw InputError("--cases", "expected an integer >= 1");
  if (!(a.case_time_limit_s >= 0.001 && a.case_time_limit_s <= 86400))
    throw InputError("--case-time-limit", "expected seconds, at least 0.001 and at most 86400");
  a.options.quiet_limit = std::chrono::milliseconds(static_cast<int64_t>(a.case_time_limit_s * 1000));
  if (!a.fmu.fmus.empty()) {
    if (a.system != "all") throw InputError("--system", "goes without --fmu (the FMUs are system A's)");
    return conform_fmu(a.fmu, a.options.cases, a.cases_given, a.options.seed, a.options.max_steps, a.options.out_dir,
                       a.case_time_limit_s, a.json);
  }
  const std::vector<std::string> systems =
      a.system == "all" ? std::vector<std::string>{"exploration", "automata", "missions"} : std::vector<std::string>{a.system};
  const mpi::Launch launch = mpi::launch_from_environment();
  if (const auto problem = counterexample_folder_problem(a.options.out_dir, launch.size <= 1)) {
    if (launch.rank == 0) throw *problem;
    return 2;   // rank 0 reports it
  }
  const bool several = systems.size() > 1;
  Json combined = Json::object();
  int status = 0;
  for (const std::string& system : systems) {
    Json one;
    Json* out = a.json && several ? &one : nullptr;
    int rc = 0;
    if (system == "exploration") {
      rc = conform_exploration(a, launch, out);
    } else {
      if (launch.rank != 0) continue;   // the other ranks only serve exploration chunks
      SystemCampaign c{a.cases_given ? a.options.cases : 0, a.options.seed, a.options.out_dir, a.json, a.stats,
                       ::isatty(2) == 1 && !a.json, a.options.quiet_limit};
      rc = system == "automata" ? conform_automata(c, out) : conform_missions(c, out);
    }
    if (rc > 1) return rc;
    status = std::max(status, rc);
    if (out) combined[system] = one;
  }
  if (a.json && several && launch.rank == 0) {
    combined["agree"] = status == 0;
    fmt::print("{}\n", combined.dump());
  }
  return status;
}

// A trace's header line. It is read with the JSON reader like every other input: a header
// nested 200 000 deep crashed the raw parser.
Json trace_header(const std::string& path) {
  io_input::check_input_file(path, "trace", false);   // a folder or /dev/zero: one message, not a hang
  std::ifstream in(path);
  std::string first;
  std::getline(in, first);
  return json_io::parse_json_text(first, path);
}

int replay(const std::string& path, const std::string& against, const Budgets& budgets) {
  // A handshake counterexample from `swarmcheck prove` is shown step by step (nothing to re-run).
  const Json header = trace_header(path);
  if (json_io::string_member(header, "system") == "handshake") return proofs::handshake::show_handshake_trace(path, stdout);
  const Engine engine = against == "model" ? Engine::model : Engine::impl;
  const ReplayResult r = replay_trace(path, engine, budgets.memory_bytes);
  if (budgets.report)   // the budget's estimate, as replay_trace checked it (the header is valid by now)
    report_memory(budgets, kProcessBytes + static_cast<double>(estimated_bytes(engine, swarmcheck::exploration::scenario_from_json(header.at("scenario")))));
  if (r.recorded) fmt::print("recorded: {}\n", *r.recorded);
  if (!r.divergence) {
    fmt::print("replay on {}: reproduces the trace ({} records agree bit for bit)\n", against, r.records);
    return 0;
  }
  const auto& d = *r.divergence;
  fmt::print("replay on {}: step {}: {} trace={} {}={} (after {} agreeing records)\n", against, d.step, d.path,
             d.model, against, d.impl, r.records - 1);
  return 1;
}

}  // namespace

void add_conform_verb(CLI::App& app, int& exit_code) {
  auto a = std::make_shared<ConformArgs>();
  CLI::App* cmd = app.add_subcommand(
      "conform", "Compare the optimised library with the reference model on generated cases");
  CLI::Option* cases = cmd->add_option("--cases", a->options.cases,
                                       "Generated cases per system (default: exploration 200, automata 400, missions 300)");
  cmd->add_option("--system", a->system, "all | exploration | automata | missions")
      ->check(CLI::IsMember({"all", "exploration", "automata", "missions"}))
      ->capture_default_str();
  cmd->add_option("--seed", a->options.seed, "The campaign's one seed")->capture_default_str()->check(seed_validator());
  cmd->add_option("--max-steps", a->options.max_steps, "Steps per case (cosim cases: 3x)")->capture_default_str();
  cmd->add_option("--out", a->options.out_dir, "Folder for counterexample traces")->capture_default_str();
  cmd->add_flag("--json", a->json, "Print the report as one JSON object");
  cmd->add_flag("--stats", a->stats, "Also report what the cases reached (families, ages, poses, ...)");
  cmd->add_option("--case-time-limit", a->case_time_limit_s,
                  "Seconds a case may run without reaching a new step before it counts as hung (each case runs in "
                  "a child process: a crash or a hang is a counterexample)")
      ->capture_default_str();
  add_conform_fmu_options(cmd, a->fmu);
  cmd->callback([a, cases, &exit_code] {
    a->cases_given = cases->count() > 0;
    exit_code = guarded([&] { return conform(*a); });
  });
}

void add_replay_verb(CLI::App& app, int& exit_code) {
  auto path = std::make_shared<std::string>();
  auto against = std::make_shared<std::string>("impl");
  CLI::App* cmd = app.add_subcommand("replay", "Re-run a trace and name the first field that differs");
  cmd->add_option("trace", *path, "A trace written by run --trace or conform")->required();
  cmd->add_option("--against", *against, "model | impl")->check(CLI::IsMember({"model", "impl"}))->capture_default_str();
  auto budgets = std::make_shared<Budgets>();
  add_budget_options(cmd, *budgets, false);
  cmd->callback([path, against, budgets, &exit_code] {
    exit_code = guarded([&] { return replay(*path, *against, *budgets); });
  });
}

}  // namespace swarmcheck::cli
