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
#include "swarmcheck/supervisor.hpp"

namespace swarmcheck::impl::supervisor {

using swarmcheck::supervisor::Automaton;
// The reader and writer are the public API's (swarmcheck/supervisor.hpp), defined in
// fsm_read.cpp and fsm_write.cpp; internal callers use them under these names too.
using swarmcheck::supervisor::read_fsm;
using swarmcheck::supervisor::read_fsm_file;
using swarmcheck::supervisor::write_fsm;

// No allocation is sized from a count in the file, but counts above these are refused anyway.
inline constexpr std::size_t kStatesMax = 100'000'000;
inline constexpr std::size_t kTransitionsPerStateMax = 1'000'000;

}  // namespace swarmcheck::impl::supervisor
