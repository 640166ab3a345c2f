#pragma once
// A Python Scenario: a validated scenario (the library's reader and validator, the CLI's
// messages) and the name its messages start with.
#include <pybind11/pybind11.h>

#include <string>

#include "spec/exploration/scenario.hpp"

namespace swarmcheck::python {

struct PyScenario {
  swarmcheck::exploration::ValidScenario valid;
  std::string where;   // "default scenario", the file, or "dict"
};

// The `run` flags as keywords (mode, rule, preset, controller, body, seed, steps) applied to `s`;
// an unknown keyword is a TypeError, a bad value a ValueError naming the keyword.
PyScenario with_keywords(PyScenario s, const pybind11::dict& keywords);

// scenario: None (the built-in default), a Scenario, a dict, or a path (str or os.PathLike) to a
// JSON file; then the keywords.
PyScenario scenario_from(const pybind11::handle& scenario, const pybind11::dict& keywords);

}  // namespace swarmcheck::python
