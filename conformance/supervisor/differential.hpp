#pragma once
// Differential runners for the automata operations: run impl/supervisor and model/supervisor on
// the same input and describe the first difference (nothing when they agree). Automata built by
// an operation are compared exactly as the user sees them: the library's own result (never a
// name-keyed copy, which would merge two states of one name) must have the model's state count,
// the model's state names in the model's order, and write the same .fsm bytes.
#include <optional>
#include <string>
#include <vector>

#include "impl/supervisor/fsm.hpp"
#include "spec/supervisor/automaton.hpp"

namespace swarmcheck::conformance::supervisor {

using swarmcheck::supervisor::Automaton;

// The automaton's accessible part with states renamed "0", "1", ... in breadth-first order from
// the initial state (events in name order), as .fsm text. Two deterministic automata have the
// same canonical text iff their accessible parts are isomorphic (same events and attributes,
// same marking, same transitions).
std::string canonical(const Automaton& a);

// The library's automaton against the model's, exactly (see above); `what` names the operation.
std::optional<std::string> diff_exact(const std::string& what, const swarmcheck::impl::supervisor::Fsm& impl,
                                      const Automaton& model);

// The unary operations, each compared exactly (they keep the input's state names):
// accessible, coaccessible, trim, blocking states, nonblocking.
std::optional<std::string> diff_unary(const Automaton& a);
// Sizes of what a comparison built (for the campaign's coverage figures).
struct BuiltSizes {
  std::size_t product_states = 0;      // the product, or the synthesis plant
  std::size_t supervisor_states = 0;
};

// The product of the parts (two or more), exactly.
std::optional<std::string> diff_product(const std::vector<Automaton>& parts, BuiltSizes* sizes = nullptr);
// Controllability of spec w.r.t. the plant (the product of plant_parts), and the supervisor, exactly.
std::optional<std::string> diff_synthesis(const std::vector<Automaton>& plant_parts, const Automaton& spec,
                                          BuiltSizes* sizes = nullptr);

// sup as a supervisor of the plant (the product of plant_parts): verdicts and witnesses exactly.
std::optional<std::string> diff_control(const std::vector<Automaton>& plant_parts, const Automaton& sup);

// Partial observation: the observer of a, exactly; observability of spec for the plant (verdict
// and witness words); the controllable normal supervisor, exactly.
std::optional<std::string> diff_observer(const Automaton& a);
std::optional<std::string> diff_observability(const std::vector<Automaton>& plant_parts, const Automaton& spec);
std::optional<std::string> diff_supcon_normal(const std::vector<Automaton>& plant_parts, const Automaton& spec,
                                              BuiltSizes* sizes = nullptr);

// L(a) in L(b) and Lm(a) in Lm(b), verdicts and witness words compared exactly.
std::optional<std::string> diff_inclusion(const Automaton& a, const Automaton& b);

}  // namespace swarmcheck::conformance::supervisor
