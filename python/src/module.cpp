// swarmcheck._swarmcheck: the library for Python (README, "Python"). The package swarmcheck
// (python/swarmcheck/__init__.py) re-exports these names.
#include "python/src/bindings.hpp"

PYBIND11_MODULE(_swarmcheck, m) {
  m.doc() = "swarmcheck's library: exploration runs and supervisor automata (see the package swarmcheck).";
  swarmcheck::python::bind_errors(m);
  swarmcheck::python::bind_scenario(m);
  swarmcheck::python::bind_simulation(m);
  swarmcheck::python::bind_overhead(m);
  swarmcheck::python::bind_automata(m);
  swarmcheck::python::bind_mission(m);
  swarmcheck::python::bind_dse(m);
  swarmcheck::python::bind_prove(m);
}
