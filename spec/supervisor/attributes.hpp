#pragma once
// Event attributes across the files of one command (SPEC.md 13.1). A `.fsm` file may leave an
// event's c|uc or o|uo unstated; what the files of one command (plants first, then
// specifications, in command-line order) state is pooled:
//   - an attribute stated by some file is the event's attribute in every file of the command;
//   - an attribute stated by no file is c (controllable) / o (observable), the UMDES defaults;
//   - an attribute stated differently by two files is bad input naming both places.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "spec/supervisor/automaton.hpp"

namespace swarmcheck::supervisor {

// One attribute as one file states it, and where ("file:line:column" of its first statement).
struct Stated {
  bool value = true;
  std::string where;
  friend bool operator==(const Stated&, const Stated&) = default;
};
struct EventStatements {
  std::optional<Stated> controllable, observable;
  friend bool operator==(const EventStatements&, const EventStatements&) = default;
};
// What one file states, for every event it names (unstated attributes empty).
using Statements = std::map<Event, EventStatements>;

// The pooled attributes of every event the files name. A conflict throws InputError at the later
// file's place, naming the earlier one: "b.fsm:4:9: event 'x' is c here but uc at a.fsm:3:9".
std::map<Event, EventAttr> resolve_attributes(const std::vector<Statements>& files);

// a with each of its events' attributes taken from `attrs` (events absent there keep theirs).
Automaton with_attributes(Automaton a, const std::map<Event, EventAttr>& attrs);

}  // namespace swarmcheck::supervisor
