#pragma once
// `swarmcheck edit [SCENARIO.json | MISSION.json]`: the editor pages. A scenario file (or none:
// the built-in default) opens the scenario editor; a mission file (it has "fsm") opens the
// mission editor with the events of the FSM it names. Files are read and checked first, like
// `run` and `mission plan` do: an editor never starts from a file the CLI would refuse.
#include <string>

#include "views/page.hpp"

namespace swarmcheck::views {

Page scenario_editor_page(const std::string& path);   // empty path: the default scenario
Page mission_editor_page(const std::string& path);
Page edit_page(const std::string& path);              // chooses by the file's content

// The live page of `serve` (the scenario editor with Run).
Page live_page();

}  // namespace swarmcheck::views
