#pragma once
// Is a model step a transition the spec allows? Checked on the observable state before and
// after one master step (spec/SPEC.md sections 6, 7 and 10). Returns "" or the first broken rule.
#include <string>

#include "spec/exploration/types.hpp"

namespace swarmcheck::conformance::exploration {

std::string check_transition(const swarmcheck::exploration::Scenario& s, const swarmcheck::exploration::StepRecord& before,
                             const swarmcheck::exploration::StepRecord& after);

}  // namespace swarmcheck::conformance::exploration
