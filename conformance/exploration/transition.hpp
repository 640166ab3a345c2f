#pragma once
// Is a model step a transition the spec allows? Checked on the observable state before and
// after one master step (spec/SPEC.md sections 6, 7 and 10). Returns "" or the first broken rule.
#include <string>

#include "spec/exploration/types.hpp"

namespace swarmcheck::conformance {

std::string check_transition(const exploration::Scenario& s, const exploration::StepRecord& before,
                             const exploration::StepRecord& after);

}  // namespace swarmcheck::conformance
