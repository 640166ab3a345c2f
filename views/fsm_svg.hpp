#pragma once
// An automaton as a picture, laid out by Graphviz `dot` (Debian's graphviz) at view time, styled
// as DES tools draw them: marked states doubled, the initial state entered by an arrow from
// nowhere, controllable events solid with a bar at the arc's tail (the tick of Wonham's notation),
// uncontrollable events dashed. Without `dot` on the PATH: an InputError that says so.
#include <atomic>
#include <chrono>
#include <optional>
#include <string>

#include "spec/supervisor/automaton.hpp"

namespace swarmcheck::views {

// Above this many transitions the layout is not attempted (dot takes minutes); the page lists
// the states instead, searchable.
inline constexpr std::size_t kLayoutTransitionsMax = 4000;

// ... and dot gets this long for one layout: a dense automaton under the cap (63 states, 3 969
// transitions) kept dot busy for hours, and a server's worker with it.
inline constexpr std::chrono::milliseconds kLayoutTimeMax{20000};

std::string styled_dot(const swarmcheck::supervisor::Automaton& a);
// Runs dot -Tsvg; nullopt when it takes longer than `limit`, or `cancel` is set meanwhile (a
// server stopping): dot is killed.
std::optional<std::string> fsm_svg_within(const swarmcheck::supervisor::Automaton& a, std::chrono::milliseconds limit,
                                          const std::atomic<bool>* cancel = nullptr);
// fsm_svg_within(a, kLayoutTimeMax), an InputError past it.
std::string fsm_svg(const swarmcheck::supervisor::Automaton& a);
bool dot_available();

}  // namespace swarmcheck::views
