#pragma once
// Export of an automaton to Graphviz DOT and to JSON (the `.fsm` form is in fsm_io.hpp).
#include <string>

#include "spec/supervisor/automaton.hpp"

namespace swarmcheck::impl::supervisor {

// digraph: marked states doubled, the initial state pointed at, uncontrollable events dashed.
std::string to_dot(const spec::supervisor::Automaton& a);

// {"initial", "states": [{"name", "marked", "transitions": [{"event", "target"}]}],
//  "events": [{"name", "controllable", "observable"}]}, indented, states in order.
std::string to_json_text(const spec::supervisor::Automaton& a);

}  // namespace swarmcheck::impl::supervisor
