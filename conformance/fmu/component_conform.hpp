#pragma once
// `conform --fmu` with one FMU: a Body or a Controller of system A alone, driven through its FMI
// 2.0 C API with generated input sequences and compared every step with the spec's step of the
// same component (spec/exploration/robot.hpp: body_advance, controller_step), whatever the rest
// of the loop would be. A Body case: a start pose (and, for the intocps body, its start heading),
// a communication step, and the servo inputs of each step, with their edge values (0, +-1, beyond
// saturation, tiny); a Controller case: poses around waypoints (arrivals, the atan2 fix's deadband,
// headings past +-pi) and the Environment's flag. The minimal failing case is written as a folder
// with the case (case.json), the first difference (divergence.json) and the model's outputs at
// every step (expected.csv) to drive the FMU with in any tool.
#include <string>

#include "conformance/fmu/fmu_conform.hpp"

namespace swarmcheck::conformance::fmu {

enum class ComponentRole { controller, body };

// The campaign over `fmu` (its role already known), with o's budget, seed, tolerance and model
// choices (o.controller_law for a Controller, o.body_kind for a Body). The FMU is unpacked under
// `scratch`, an existing folder emptied after each case.
FmuConformReport run_component_conform(const FmuConformOptions& o, const std::string& fmu, ComponentRole role,
                                       const std::string& scratch);

}  // namespace swarmcheck::conformance::fmu
