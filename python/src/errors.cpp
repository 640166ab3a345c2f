// Bad input never crashes the interpreter: the library's InputError (file:line:column or a JSON
// path, then what was expected: the CLI's message, without its "swarmcheck: error: " prefix)
// becomes swarmcheck.InputError, a ValueError.
#include <pybind11/pybind11.h>

#include "python/src/bindings.hpp"
#include "spec/util/input_error.hpp"

namespace py = pybind11;

namespace swarmcheck::python {

void bind_errors(py::module_& m) {
  auto& error = py::register_exception<InputError>(m, "InputError", PyExc_ValueError);
  error.attr("__doc__") = "Bad input: the command line's message (file:line:column or a JSON path, then what was "
                          "expected), without its 'swarmcheck: error: ' prefix. A ValueError.";
  // What a budget or a buffer could not foresee: MemoryError, as Python's own allocations.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const std::bad_alloc&) {
      PyErr_SetString(PyExc_MemoryError, "out of memory (lower the input's size)");
    }
  });
}

}  // namespace swarmcheck::python
