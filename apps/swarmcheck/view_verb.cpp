// swarmcheck view: one self-contained HTML file (no network: scripts, styles and data inlined) for
// an exploration trace, a conformance counterexample, a proof counterexample trace, a mission
// trace or an .fsm automaton. Bad input: one message, status 2, and no output file.
#include "apps/swarmcheck/view_verb.hpp"

#include <fmt/core.h>

#include "apps/swarmcheck/verb.hpp"
#include "impl/io/atomic_file.hpp"
#include "proofs/obligations/handshake_trace.hpp"
#include "views/view.hpp"

namespace swarmcheck::cli {
namespace {

struct ViewCliOptions {
  std::string file;
  std::string out;
  views::ViewOptions view;
};

int run_view(const ViewCliOptions& o) {
  const std::string text = views::read_text_file(o.file, "file to view");
  const views::ViewKind kind = views::detect_view_kind(text, o.file);
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
      "view", "Write a self-contained HTML view of a trace (run, conform, prove, mission) or an .fsm automaton");
  cmd->add_option("file", o->file, "The trace (.jsonl) or automaton (.fsm)")->required()->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", o->out, "The HTML file to write")->required();
  cmd->add_option("--max-records", o->view.max_records, "Longer traces are thinned evenly to this many records")
      ->capture_default_str();
  cmd->add_option("--mission", o->view.mission_path, "A mission trace's mission file (default: the one its header names)");
  cmd->callback([o, &exit_code] { exit_code = guarded([&] { return run_view(*o); }); });
}

}  // namespace swarmcheck::cli
