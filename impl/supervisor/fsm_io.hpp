#pragma once
// The UMDES `.fsm` text format (DESIGN.md B1), read liberally and written precisely.
//
//   <number of states>
//   <state> <marked 0|1> <number of transitions>        one block per state; the first block
//   <event> <target> [c|uc] [o|uo] [probability]        is the initial state
//   ...
//   EVENTS                                               optional, after the last block:
//   <event> [c|uc] [o|uo]                                events that may have no transition
//
// Reading: fields are separated by any run of spaces or tabs; blank lines (and CR of CRLF) are
// ignored anywhere; an omitted attribute takes the value the same event states elsewhere in the
// file, else c / o (the UMDES defaults); a trailing probability field is accepted and dropped.
// Every error is an InputError at "file:line:column" saying what was expected.
//
// Writing: the count, a blank line, then each block: fields separated by one tab, transitions in
// event-name order, attributes always written, a blank line after each block; an EVENTS section
// only for events that have no transition.
#include <string>
#include <string_view>

#include "spec/supervisor/automaton.hpp"

namespace swarmcheck::impl::supervisor {

using spec::supervisor::Automaton;

// No allocation is sized from a count in the file, but counts above these are refused anyway.
inline constexpr std::size_t kStatesMax = 100'000'000;
inline constexpr std::size_t kTransitionsPerStateMax = 1'000'000;

// `source` names the text in error messages (usually the path).
Automaton read_fsm(std::string_view text, const std::string& source);
// Reads the file at `path`; a file that cannot be opened is an InputError too.
Automaton read_fsm_file(const std::string& path);

std::string write_fsm(const Automaton& a);

// Writes `content` to `path` through a temporary file in the same folder and a rename, so the
// path holds either its old content or the whole new one. Failure is an InputError.
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace swarmcheck::impl::supervisor
