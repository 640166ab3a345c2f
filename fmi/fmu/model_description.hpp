#pragma once
// modelDescription.xml of an FMU (FMI 2.0, co-simulation), written from the component's bound
// variables (variable_table.hpp): every variable with its start value where FMI 2.0 wants one
// (parameters, constants, inputs), ModelStructure listing every output (no direct feedthrough:
// empty dependencies) and, as InitialUnknowns, every output (initial = calculated).
#include <string>

#include "fmi/fmu/component.hpp"

namespace swarmcheck::fmi {

std::string model_description_xml(const FmuSetup& setup, const std::string& tool_version);

}  // namespace swarmcheck::fmi
