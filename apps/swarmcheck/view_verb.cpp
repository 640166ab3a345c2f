// swarmcheck view: one self-contained HTML file (no network: scripts, styles and data inlined) for
// an exploration trace, a conformance counterexample, a proof counterexample trace, a mission
// trace, an .fsm automaton, or a DSE results folder. Bad input: one message, status 2, and no
// output file.
#include "apps/swarmcheck/view_verb.hpp"

#include <fmt/core.h>

#include <filesystem>

#include "apps/swarmcheck/verb.hpp"
#include "impl/io/atomic_file.hpp"
#include "spec/util/input_error.hpp"
#include "spec/util/json_text.hpp"
#include "proofs/obligations/handshake_trace.hpp"
#include "swarmcheck/mission.hpp"
#include "views/view.hpp"

namespace swarmcheck::cli {
namespace {

struct ViewCliOptions {
  std::string file;
  std::string out;
  views::ViewOptions view;
};

// A `swarmcheck dse` output folder: its report.html already is the self-contained page of the
// sweep (ranking table, Pareto scatter, one response plot per parameter), written from the same
// results as results.json, so the view is that page, once the folder is checked to be a DSE's.
int view_dse_folder(const ViewCliOptions& o) {
  const std::filesystem::path dir(o.file);
  const std::string results_path = (dir / "results.json").string();
  if (!std::filesystem::is_regular_file(dir / "results.json"))
    throw InputError(o.file, "a folder to view must be a `swarmcheck dse` output folder, with results.json");
  const json_io::Json results = json_io::parse_json_text(views::read_text_file(results_path, "DSE results"), results_path);
  if (!results.is_object() || results.value("format", json_io::Json()) != "swarmcheck-dse-results")
    throw InputError(results_path, "format: expected \"swarmcheck-dse-results\" (a file `swarmcheck dse` writes)");
  if (!results.contains("points") || !results["points"].is_array())
    throw InputError(results_path, "points: expected the list of design points (a file `swarmcheck dse` writes)");
  const json_io::Json& points = results["points"];
  for (std::size_t k = 0; k < points.size(); ++k)
    if (!points[k].is_object() || !points[k].contains("parameters"))
      throw InputError(results_path, "points[" + std::to_string(k) + "]: expected a design point (an object with \"parameters\")");
  const std::string report_path = (dir / "report.html").string();
  if (!std::filesystem::is_regular_file(dir / "report.html"))
    throw InputError(report_path, "missing: rerun `swarmcheck dse` with -o " + o.file + " (it resumes from its journal)");
  const std::string report = views::read_text_file(report_path, "DSE report");
  // The page is copied as it is: it must be the one `swarmcheck dse` writes, not any file.
  if (report.rfind("<!DOCTYPE html>", 0) != 0 || report.find("<title>swarmcheck DSE: ") > 200)
    throw InputError(report_path, "expected the report `swarmcheck dse` writes (an HTML page titled \"swarmcheck DSE: ...\"); "
                                  "rerun `swarmcheck dse` with -o " + o.file);
  io::write_file_atomically(o.out, report);
  fmt::print("{}: dse view of {} ({} design points)\n", o.out, o.file, points.size());
  return 0;
}

int run_view(const ViewCliOptions& o) {
  impl::io::refuse_output_that_is_an_input(o.out, {o.file, o.view.mission_path});
  if (std::filesystem::is_directory(o.file)) return view_dse_folder(o);
  const std::string text = views::read_text_file(o.file, "file to view");
  const views::ViewKind kind = views::detect_view_kind(text, o.file);
  if (kind == views::ViewKind::mission)   // the mission it is shown with, and that mission's .fsm
    impl::io::refuse_output_that_is_an_input(
        o.out, swarmcheck::mission::mission_input_files(views::mission_file_of_trace(text, o.file, o.view)));
  views::Page page;
  if (kind == views::ViewKind::handshake) {
    proofs::handshake::read_handshake_trace(o.file);   // checks every line (proofs/' reader)
    page = views::handshake_page(text, o.file);
  } else {
    page = views::view_page(o.file, o.view);
  }
  io::write_file_atomically(o.out, views::assemble_page(page));
  fmt::print("{}: {} view of {}\n", o.out, page.data["kind"].get<std::string>(), o.file);
  return 0;
}

}  // namespace

void add_view_verb(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<ViewCliOptions>();
  CLI::App* cmd = app.add_subcommand(
      "view", "Write a self-contained HTML view of a trace (run, conform, prove, mission), an .fsm automaton or a DSE output folder");
  cmd->add_option("file", o->file, "The trace (.jsonl), automaton (.fsm) or `swarmcheck dse` output folder")
      ->required()
      ->check(CLI::ExistingPath);
  cmd->add_option("-o,--output", o->out, "The HTML file to write")->required();
  cmd->add_option("--max-records", o->view.max_records, "Longer traces are thinned evenly to this many records")
      ->capture_default_str();
  cmd->add_option("--mission", o->view.mission_path, "A mission trace's mission file (default: the file of the name its header gives, next to the trace)");
  cmd->callback([o, &exit_code] { exit_code = guarded([&] { return run_view(*o); }); });
}

}  // namespace swarmcheck::cli
