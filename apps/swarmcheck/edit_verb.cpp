// swarmcheck edit: the scenario editor (no file, or a scenario) or the mission editor (a mission
// file), as one self-contained HTML file. The file is checked first, as `run` / `mission plan`
// check it: bad input gets one message, status 2, and no output file.
#include "apps/swarmcheck/edit_verb.hpp"

#include <fmt/core.h>

#include "apps/swarmcheck/verb.hpp"
#include "impl/io/atomic_file.hpp"
#include "swarmcheck/mission.hpp"
#include "views/edit.hpp"

namespace swarmcheck::cli {
namespace {

struct EditOptions {
  std::string file;
  std::string out;
};

int run_edit(const EditOptions& o) {
  io::refuse_output_that_is_an_input(o.out, {o.file});
  const views::Page page = views::edit_page(o.file);
  if (page.data["kind"].get<std::string>() != "editor")   // a mission: its .fsm is an input too
    io::refuse_output_that_is_an_input(o.out, swarmcheck::mission::mission_input_files(o.file));
  io::write_file_atomically(o.out, views::assemble_page(page));
  fmt::print("{}: {} for {}\n", o.out, page.data["kind"].get<std::string>() == "editor" ? "scenario editor" : "mission editor",
             o.file.empty() ? "the default scenario" : o.file);
  return 0;
}

}  // namespace

void add_edit_verb(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<EditOptions>();
  CLI::App* cmd = app.add_subcommand("edit", "Write an HTML editor for a scenario (default: the built-in one) or a mission");
  cmd->add_option("file", o->file, "SCENARIO.json or MISSION.json");
  cmd->add_option("-o,--output", o->out, "The HTML file to write")->required();
  cmd->callback([o, &exit_code] { exit_code = guarded([&] { return run_edit(*o); }); });
}

}  // namespace swarmcheck::cli
