// The `.fsm` writer (precise form, see fsm_io.hpp).
#include "impl/supervisor/fsm_io.hpp"
#include "spec/util/demand.hpp"

namespace swarmcheck::supervisor {

namespace {

std::string attrs(const EventAttr& a) {
  return std::string(a.controllable ? "c" : "uc") + "\t" + (a.observable ? "o" : "uo");
}

}  // namespace

std::string write_fsm(const Automaton& a) {
  // Our own operations only produce well-formed automata; writing another is a bug.
  SWARM_DEMAND(well_formedness_error(a).empty());
  std::string out = std::to_string(a.states.size()) + "\n\n";
  for (const auto& q : a.states) {
    const auto row = a.delta.find(q);
    const std::size_t n = row == a.delta.end() ? 0 : row->second.size();
    out += q + "\t" + (a.marked.count(q) ? "1" : "0") + "\t" + std::to_string(n) + "\n";
    if (n > 0)
      for (const auto& [e, target] : row->second)
        out += e + "\t" + target + "\t" + attrs(a.events.at(e)) + "\n";
    out += "\n";
  }
  std::set<std::string> used;
  for (const auto& [q, row] : a.delta)
    for (const auto& [e, target] : row) used.insert(e);
  bool header = false;
  for (const auto& [e, attr] : a.events) {
    if (used.count(e)) continue;
    if (!header) out += "EVENTS\n";
    header = true;
    out += e + "\t" + attrs(attr) + "\n";
  }
  return out;
}

}  // namespace swarmcheck::supervisor
