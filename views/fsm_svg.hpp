#pragma once
// An automaton as a picture, laid out by Graphviz `dot` (Debian's graphviz) at view time, styled
// as DES tools draw them: marked states doubled, the initial state entered by an arrow from
// nowhere, controllable events solid with a bar at the arc's tail (the tick of Wonham's notation),
// uncontrollable events dashed. Without `dot` on the PATH: an InputError that says so.
#include <string>

#include "spec/supervisor/automaton.hpp"

namespace swarmcheck::views {

// Above this many transitions the layout is not attempted (dot takes minutes); the page lists
// the states instead, searchable.
inline constexpr std::size_t kLayoutTransitionsMax = 4000;

std::string styled_dot(const swarmcheck::supervisor::Automaton& a);
std::string fsm_svg(const swarmcheck::supervisor::Automaton& a);   // runs dot -Tsvg
bool dot_available();

}  // namespace swarmcheck::views
