#pragma once
// An FMI 2.0 model description checker of our own (the standard's rules, section 2.2, checked
// with a real XML parser, libxml2): required attributes, legal causality / variability / initial
// combinations (the standard's tables), start values exactly where they are required, unique
// names and value references, one type element per variable, and a ModelStructure whose
// Outputs are exactly the outputs and whose InitialUnknowns are exactly the outputs with initial
// calculated or approx (and calculated parameters), in ascending index order.
#include <string>
#include <vector>

namespace swarmcheck::testing {

// Every rule broken, one line each (empty: the description is valid).
std::vector<std::string> fmi2_problems(const std::string& model_description_xml);

}  // namespace swarmcheck::testing
