#pragma once
// The pieces of the `swarmcheck._swarmcheck` extension, one file each, registered by module.cpp.
#include <pybind11/pybind11.h>

namespace swarmcheck::python {

void bind_errors(pybind11::module_& m);       // errors.cpp: InputError -> ValueError
void bind_scenario(pybind11::module_& m);     // scenario_bindings.cpp
void bind_simulation(pybind11::module_& m);   // simulation_bindings.cpp: Simulation, run()
void bind_overhead(pybind11::module_& m);     // overhead_bindings.cpp: the library timed alone
void bind_automata(pybind11::module_& m);     // automaton_bindings.cpp
void bind_mission(pybind11::module_& m);      // mission_bindings.cpp
void bind_dse(pybind11::module_& m);          // dse_bindings.cpp
void bind_prove(pybind11::module_& m);        // prove_bindings.cpp

}  // namespace swarmcheck::python
