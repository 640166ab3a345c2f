#pragma once
// The two engines of the automata operations behind one interface: the library users link
// (swarmcheck/supervisor.hpp) and the reference model (the oracle). The command line's
// `fsm ... --engine impl|model` chooses here, so that only the harness ever reaches into model/.
// Both engines give the same results (the conformance campaign checks it).
#include <string>
#include <vector>

#include "swarmcheck/supervisor.hpp"

namespace swarmcheck::conformance::supervisor {

using swarmcheck::supervisor::Automaton;

enum class Engine { impl, model };

// "impl" or "model"; anything else is an InputError.
Engine engine_named(const std::string& name);

swarmcheck::supervisor::CheckReport check(const Automaton& a, Engine engine);
bool is_nonblocking(const Automaton& a, Engine engine);
// max_bytes: the impl's memory budget (product, supcon); the model, the oracle, has none.
Automaton product(const std::vector<Automaton>& parts, const std::vector<std::string>& names,
                  Engine engine, std::uint64_t max_bytes = 0);
bool is_controllable(const Automaton& plant, const Automaton& spec, Engine engine);
swarmcheck::supervisor::ControlReport control_report(const Automaton& plant, const Automaton& sup,
                                                     Engine engine);
Automaton supcon(const Automaton& plant, const Automaton& spec, Engine engine, std::uint64_t max_bytes = 0);
Automaton observer(const Automaton& a, Engine engine, std::uint64_t max_bytes = 0);
swarmcheck::supervisor::ObservabilityReport observability(const Automaton& plant, const Automaton& spec,
                                                          Engine engine);
Automaton supcon_normal(const Automaton& plant, const Automaton& spec, Engine engine, std::uint64_t max_bytes = 0);
swarmcheck::supervisor::Inclusion language_inclusion(const Automaton& a, const Automaton& b,
                                                     Engine engine);

}  // namespace swarmcheck::conformance::supervisor
