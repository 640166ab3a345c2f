// swarmcheck conform / replay: the differential harness on the command line.
#include "apps/swarmcheck/conform_verb.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <fstream>
#include <memory>

#include "apps/swarmcheck/verb.hpp"
#include "conformance/exploration/conform.hpp"
#include "conformance/exploration/trace_io.hpp"
#include "proofs/obligations/handshake_trace.hpp"
#include "spec/util/hana_json.hpp"

namespace swarmcheck::cli {
namespace {

using namespace swarmcheck::conformance;
using json_io::Json;

struct ConformArgs {
  ConformOptions options;
  bool json = false;
};

Json case_summary(const ExplorationCase& c) {
  const auto& s = c.scenario;
  return Json{{"map_size", s.map_size}, {"robots", s.robots.size()}, {"obstacles", s.obstacles.size()},
              {"rule", json_io::enum_to_string(s.rule)}, {"mode", json_io::enum_to_string(s.mode)},
              {"grouped", c.grouped}};
}

int conform(ConformArgs a) {
  const bool tty = ::isatty(2) == 1 && !a.json;
  if (tty)
    a.options.on_case = [](int done, int asked) {
      if (done % 10 == 0 || done == asked) fmt::print(stderr, "\rcase {} / {}", done, asked);
    };
  const ConformReport r = run_conform(a.options);
  if (tty) fmt::print(stderr, "\r{:40}\r", "");
  const auto& cx = r.counterexample;
  if (a.json) {
    Json j{{"agree", !cx.has_value()}, {"cases_run", r.cases_run}, {"seed", a.options.seed}};
    if (cx)
      j["counterexample"] = {{"trace", cx->trace_path}, {"step", cx->divergence.step},
                             {"path", cx->divergence.path}, {"text", cx->divergence.describe()},
                             {"shrinks", cx->shrinks}, {"case", case_summary(cx->minimal)}};
    fmt::print("{}\n", j.dump());
  } else if (!cx) {
    fmt::print("conform: impl and model agree bit for bit on {} cases (seed {})\n", r.cases_run, a.options.seed);
  } else {
    const auto& s = cx->minimal.scenario;
    fmt::print("conform: DIVERGENCE after {} cases (seed {}); shrunk {} times to map {}, {} robots, "
               "{} obstacles, rule {}, mode {}\n  {}\n  trace: {}\n  replay: swarmcheck replay {}\n",
               r.cases_run, a.options.seed, cx->shrinks, s.map_size, s.robots.size(), s.obstacles.size(),
               json_io::enum_to_string(s.rule), json_io::enum_to_string(s.mode), cx->divergence.describe(),
               cx->trace_path, cx->trace_path);
  }
  return cx ? 1 : 0;
}

// The "system" of a trace's header line ("" when the first line is not a JSON object).
std::string trace_system(const std::string& path) {
  std::ifstream in(path);
  std::string first;
  std::getline(in, first);
  const Json h = Json::parse(first, nullptr, false);
  return h.is_object() ? h.value("system", "") : "";
}

int replay(const std::string& path, const std::string& against) {
  // A handshake counterexample from `swarmcheck prove` is shown step by step (nothing to re-run).
  if (trace_system(path) == "handshake") return proofs::handshake::show_handshake_trace(path, stdout);
  const Engine engine = against == "model" ? Engine::model : Engine::impl;
  const ReplayResult r = replay_trace(path, engine);
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
  cmd->add_option("--cases", a->options.cases, "Generated cases")->capture_default_str();
  cmd->add_option("--seed", a->options.seed, "The campaign's one seed")->capture_default_str();
  cmd->add_option("--max-steps", a->options.max_steps, "Steps per case (cosim cases: 3x)")->capture_default_str();
  cmd->add_option("--out", a->options.out_dir, "Folder for counterexample traces")->capture_default_str();
  cmd->add_flag("--json", a->json, "Print the report as one JSON object");
  cmd->callback([a, &exit_code] { exit_code = guarded([&] { return conform(*a); }); });
}

void add_replay_verb(CLI::App& app, int& exit_code) {
  auto path = std::make_shared<std::string>();
  auto against = std::make_shared<std::string>("impl");
  CLI::App* cmd = app.add_subcommand("replay", "Re-run a trace and name the first field that differs");
  cmd->add_option("trace", *path, "A trace written by run --trace or conform")->required()->check(CLI::ExistingFile);
  cmd->add_option("--against", *against, "model | impl")->check(CLI::IsMember({"model", "impl"}))->capture_default_str();
  cmd->callback([path, against, &exit_code] { exit_code = guarded([&] { return replay(*path, *against); }); });
}

}  // namespace swarmcheck::cli
