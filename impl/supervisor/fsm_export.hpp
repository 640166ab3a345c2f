#pragma once
// Export of an automaton to Graphviz DOT and to JSON (the `.fsm` form is in fsm_io.hpp): the
// public API's functions (swarmcheck/supervisor.hpp, defined in fsm_export.cpp), under the
// library's internal names too.
#include "swarmcheck/supervisor.hpp"

namespace swarmcheck::impl::supervisor {

using swarmcheck::supervisor::to_dot;
using swarmcheck::supervisor::to_json_text;

}  // namespace swarmcheck::impl::supervisor
