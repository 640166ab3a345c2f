#pragma once
// swarmcheck: discrete-event automata and supervisors (system B, part 1). Link swarmcheck::swarmcheck
// (or swarmcheck::supervisor alone).
//
//   #include <swarmcheck/supervisor.hpp>
//   namespace sv = swarmcheck::supervisor;
//   const sv::Automaton control2 = sv::read_fsm_file("control2.fsm");  // throws swarmcheck::InputError
//   const sv::CheckReport r = sv::check(control2);
//   std::printf("%zu states, nonblocking: %s\n", control2.states.size(), r.nonblocking() ? "yes" : "no");
//   const sv::Automaton plant = sv::product({sv::read_fsm_file("region_a.fsm"), sv::read_fsm_file("tasks_a.fsm")});
//   const sv::Automaton sup = sv::supcon(plant, sv::read_fsm_file("avoidance.fsm"));
//   sv::write_fsm_file("supervisor.fsm", sup);                         // whole or not at all
//   const sv::Inclusion in = sv::language_inclusion(sup, control2);   // with shortest witnesses
//
// An Automaton is a plain value (spec/supervisor/automaton.hpp: states[0] is initial, delta is a
// partial function). Every operation gives the automaton the reference model gives, state for
// state, names included (swarmcheck's conformance harness checks it); inside, automata are
// compiled to integer ids and compressed adjacency, products are built on the fly (accessible
// tuples only) and the supervisor fixpoint removes states incrementally.
#include <string>
#include <string_view>
#include <vector>

#include "spec/supervisor/attributes.hpp"
#include "spec/supervisor/automaton.hpp"
#include "spec/supervisor/control.hpp"
#include "spec/supervisor/observation.hpp"
#include "spec/supervisor/semantics.hpp"
#include "spec/util/input_error.hpp"

namespace swarmcheck::supervisor {

// ---- the UMDES .fsm format (read liberally, written precisely: docs/supervisor.md) ------------

// `source` names the text in error messages. Bad text: InputError at "source:line:column".
Automaton read_fsm(std::string_view text, const std::string& source);
Automaton read_fsm_file(const std::string& path);
// The files of one command (plants, then specifications): an attribute (c|uc, o|uo) a file
// leaves unstated is taken from the files that state it; two files stating it differently is an
// InputError naming both files and lines (spec/supervisor/attributes.hpp).
std::vector<Automaton> read_fsm_files(const std::vector<std::string>& paths);
std::string write_fsm(const Automaton& a);
// Through a temporary file and a rename: the file is written whole or left as it was.
void write_fsm_file(const std::string& path, const Automaton& a);

// Graphviz DOT (marked states doubled, uncontrollable events dashed) and JSON.
std::string to_dot(const Automaton& a);
std::string to_json_text(const Automaton& a);

// ---- checks ------------------------------------------------------------------------------------

struct CheckReport {
  std::vector<State> unreachable_states;  // not accessible, in the order of a.states
  std::vector<State> blocking_states;     // accessible but unable to reach a marked state, in order
  bool coaccessible = true;               // every state (reachable or not) can reach a marked one
  bool accessible() const { return unreachable_states.empty(); }
  bool nonblocking() const { return blocking_states.empty(); }
};
CheckReport check(const Automaton& a);
bool is_nonblocking(const Automaton& a);

// ---- operations (each equal to the reference model's result) ------------------------------------

Automaton accessible_part(const Automaton& a);
Automaton trim(const Automaton& a);
// The synchronous product (accessible part), states named "x1.x2...", breadth first. `names`
// name the parts in error messages (an event controllable in one and not in another); by
// default "part 1", "part 2", ...
// max_bytes (0: none): stop with a swarmcheck::BudgetExceeded (an InputError) once the product's
// estimated size passes it.
Automaton product(const std::vector<Automaton>& parts, const std::vector<std::string>& names = {},
                  std::uint64_t max_bytes = 0);
// Is spec controllable with respect to plant?
bool is_controllable(const Automaton& plant, const Automaton& spec);
// sup as a supervisor of plant: controllable? the closed loop nonblocking? with shortest witnesses
// (spec/supervisor/control.hpp).
ControlReport control_report(const Automaton& plant, const Automaton& sup);
// The supremal controllable nonblocking supervisor (the empty automaton when none exists).
Automaton supcon(const Automaton& plant, const Automaton& spec, std::uint64_t max_bytes = 0);
// ---- partial observation (`uo` events; spec/supervisor/observation.hpp) --------------------------

// The observer: the natural projection onto the observable events, determinised (states "{q,r}").
// max_bytes as for supcon (0: none): the subset construction can be exponential in the states.
Automaton observer(const Automaton& a, std::uint64_t max_bytes = 0);
// Is L(plant || spec) observable for plant? With two words of one projection as a witness.
ObservabilityReport observability(const Automaton& plant, const Automaton& spec);
// The supremal controllable, normal and nonblocking supervisor (states "x.y.o<k>", k the
// observer class); supcon's language when no event is unobservable.
Automaton supcon_normal(const Automaton& plant, const Automaton& spec, std::uint64_t max_bytes = 0);

// L(a) in L(b) and Lm(a) in Lm(b), each with its shortlex-least witness when it fails.
Inclusion language_inclusion(const Automaton& a, const Automaton& b);

}  // namespace swarmcheck::supervisor
