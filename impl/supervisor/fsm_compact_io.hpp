#pragma once
// The `.fsm` format (fsm_io.hpp) read into and written from the compact automaton (Fsm) without
// an Automaton value in between: for the command line on automata of millions of states, where
// the value's maps of strings cost gigabytes. Same text, same errors, same bytes as
// read_fsm / write_fsm (tests/supervisor/fsm_io_test.cpp checks both ways).
#include <ostream>
#include <string>
#include <string_view>

#include "impl/supervisor/fsm.hpp"

namespace swarmcheck::impl::supervisor {

// Bad text: InputError at "source:line:column", exactly as read_fsm.
Fsm read_fsm_compact(std::string_view text, const std::string& source);
Fsm read_fsm_compact_file(const std::string& path);

// write_fsm(decompile(f)) byte for byte, with each state spelled by `name` when it is written.
void write_fsm_compact(std::ostream& out, const Fsm& f, const AppendName& name);
std::string write_fsm_compact(const Fsm& f, const AppendName& name);
// Through a temporary file and a rename, as write_fsm_file.
void write_fsm_compact_file(const std::string& path, const Fsm& f, const AppendName& name);

}  // namespace swarmcheck::impl::supervisor
