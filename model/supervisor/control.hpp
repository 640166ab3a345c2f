#pragma once
// The reference model of a given supervisor's checks (spec/supervisor/control.hpp): a
// breadth-first search over the closed loop that keeps each state's whole word.
#include "model/supervisor/operations.hpp"
#include "spec/supervisor/control.hpp"

namespace swarmcheck::model::supervisor {

using swarmcheck::supervisor::ControlReport;

ControlReport control_report(const Automaton& plant, const Automaton& sup);

}  // namespace swarmcheck::model::supervisor
