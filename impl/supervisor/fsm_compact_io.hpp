#pragma once
// The `.fsm` format (fsm_io.hpp) read into and written from the compact automaton (Fsm) without
// an Automaton value in between: for the command line on automata of millions of states, where
// the value's maps of strings cost gigabytes. Same text, same errors, same bytes as
// read_fsm / write_fsm (tests/supervisor/fsm_io_test.cpp checks both ways).
#include <ostream>
#include <string>
#include <string_view>

#include <vector>

#include "impl/supervisor/fsm.hpp"
#include "spec/supervisor/attributes.hpp"

namespace swarmcheck::impl::supervisor {

// Bad text: InputError at "source:line:column", exactly as read_fsm. `stated`, when given,
// receives what the file states about each event's attributes, and where.
Fsm read_fsm_compact(std::string_view text, const std::string& source,
                     swarmcheck::supervisor::Statements* stated = nullptr);
Fsm read_fsm_compact_file(const std::string& path,
                          swarmcheck::supervisor::Statements* stated = nullptr);
// The files of one command, with the attributes pooled across them (spec/supervisor/attributes.hpp):
// read_fsm_files of the public API, on the compact form.
std::vector<Fsm> read_fsm_compact_files(const std::vector<std::string>& paths);

// write_fsm(decompile(f)) byte for byte, with each state spelled by `name` when it is written.
void write_fsm_compact(std::ostream& out, const Fsm& f, const AppendName& name);
std::string write_fsm_compact(const Fsm& f, const AppendName& name);
// Through a temporary file and a rename, as write_fsm_file.
void write_fsm_compact_file(const std::string& path, const Fsm& f, const AppendName& name);

}  // namespace swarmcheck::impl::supervisor
