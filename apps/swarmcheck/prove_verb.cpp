// `swarmcheck prove`: runs each obligation in its own process under a watchdog (runner.hpp),
// prints a table or JSON, and writes the SMT-LIB2 queries and counterexample traces whole or
// not at all (impl::io::AtomicFile).
#include "apps/swarmcheck/prove_verb.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "impl/io/atomic_file.hpp"
#include "apps/swarmcheck/verb.hpp"
#include "proofs/obligations/report_json.hpp"
#include "proofs/obligations/runner.hpp"

namespace swarmcheck::cli {
namespace {

using proofs::ObligationReport;

struct ProveOptions {
  std::string only;
  std::string smt2_dir;
  std::string trace_dir;
  bool json = false;
  double timeout_s = proofs::kObligationTimeoutS;   // per obligation; each takes far less
};

std::vector<const proofs::Obligation*> selected(const ProveOptions& o) {
  std::vector<const proofs::Obligation*> out;
  if (o.only.empty()) {
    for (const proofs::Obligation& ob : proofs::all_obligations()) out.push_back(&ob);
    return out;
  }
  if (const proofs::Obligation* ob = proofs::find_obligation(o.only)) return {ob};
  std::string names;
  for (const proofs::Obligation& ob : proofs::all_obligations())
    names += (names.empty() ? "" : ", ") + ob.name;
  throw InputError("--only " + o.only, "no such obligation; the obligations are: " + names);
}

// An existing folder, or one we can create; anything else is bad input.
std::filesystem::path output_dir(const std::string& dir, const char* option) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw InputError(std::string(option) + " " + dir, "cannot create or use this folder");
  return dir;
}

void write_file(const std::filesystem::path& path, const std::string& text) {
  impl::io::AtomicFile f(path.string());
  f.stream() << text;
  f.commit();
}

// One file per query: "<obligation>-<NN>-<label>.smt2", its first line the answer Z3 gave here.
void write_smt2(const std::filesystem::path& dir, const ObligationReport& r) {
  for (std::size_t k = 0; k < r.queries.size(); ++k) {
    const proofs::QueryRecord& q = r.queries[k];
    write_file(dir / fmt::format("{}-{:02}-{}.smt2", r.name, k, q.label),
               fmt::format("; swarmcheck prove: obligation {}, query {}\n; expect: {}\n{}", r.name,
                           q.label, q.answer, q.smt2));
  }
}

void print_table(const std::vector<ObligationReport>& reports, double total) {
  fmt::print("{:<32} {:<9} {:<9} {:>8}\n", "obligation", "expected", "result", "seconds");
  for (const ObligationReport& r : reports)
    fmt::print("{:<32} {:<9} {:<9} {:>8.3f}{}\n", r.name, proofs::to_string(r.expected),
               proofs::to_string(r.result), r.seconds,
               r.result != r.expected ? "   <- NOT AS EXPECTED"
               : !r.unread.empty()    ? "   <- DOES NOT READ WHAT THE STEP CALLS"
                                      : "");
  fmt::print("total {:.3f} s\n", total);
  for (const ObligationReport& r : reports) {
    fmt::print("\n{}: {}\n  {}\n", r.name, r.property, r.detail);
    if (!r.reads.empty()) fmt::print("  reads: {}\n", fmt::join(r.reads, ", "));
    if (!r.step_calls.empty()) fmt::print("  the step calls: {}\n", fmt::join(r.step_calls, ", "));
    if (!r.unread.empty()) fmt::print("  NOT READ (the step calls them on the property's path): {}\n", fmt::join(r.unread, ", "));
  }
}

int run_prove(const ProveOptions& o) {
  const auto obligations = selected(o);
  std::filesystem::path smt2_dir, trace_dir;
  if (!o.smt2_dir.empty()) smt2_dir = output_dir(o.smt2_dir, "--smt2");
  if (!o.trace_dir.empty()) trace_dir = output_dir(o.trace_dir, "--trace-dir");
  std::vector<ObligationReport> reports;
  std::vector<std::string> traces;
  double total = 0;
  for (const proofs::Obligation* ob : obligations) {
    reports.push_back(proofs::run_isolated(*ob, o.timeout_s, proofs::kQueryTimeoutMs));
    const ObligationReport& r = reports.back();
    total += r.seconds;
    if (!smt2_dir.empty()) write_smt2(smt2_dir, r);
    traces.emplace_back();
    if (r.trace && !trace_dir.empty()) {
      const auto path = trace_dir / r.trace->file_name;
      write_file(path, r.trace->text);
      traces.back() = path.string();
    }
  }
  if (o.json)
    fmt::print("{}\n", proofs::prove_report_json(reports, total, traces).dump(2));
  else
    print_table(reports, total);
  for (const ObligationReport& r : reports)
    if (!r.met()) return 1;
  return 0;
}

}  // namespace

void add_prove_verb(CLI::App& app, int& exit_code) {
  auto opts = std::make_shared<ProveOptions>();
  CLI::App* sub = app.add_subcommand(
      "prove", "Check the Z3 proof obligations (servo, atan2 fix, handshake, pheromone, occupancy)");
  sub->add_option("--only", opts->only, "Check only the obligation with this name")
      ->check(CLI::Validator([](const std::string& t) { return t.empty() ? std::string("expected an obligation's name, got nothing") : std::string(); }, "NAME"));
  sub->add_option("--smt2", opts->smt2_dir, "Write every query as SMT-LIB2 into this folder");
  sub->add_option("--trace-dir", opts->trace_dir,
                  "Write the counterexample trace of each refuted protocol obligation here");
  sub->add_flag("--json", opts->json, "Print the results as JSON");
  sub->add_option("--timeout", opts->timeout_s,
                  "Seconds per obligation before the watchdog kills its prover (default 120)")
      ->check(CLI::Validator(
          [](const std::string& text) -> std::string {
            // NaN passes every range check, and a huge value overflows the watchdog's deadline.
            const double v = std::strtod(text.c_str(), nullptr);
            if (!(v > 0 && v <= 86400)) return "expected seconds in (0, 86400], got " + text;
            return {};
          },
          "SECONDS"));
  sub->callback([opts, &exit_code] { exit_code = guarded([&] { return run_prove(*opts); }); });
}

}  // namespace swarmcheck::cli
