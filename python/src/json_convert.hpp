#pragma once
// JSON values (nlohmann::ordered_json, the library's json_io::Json) to Python values and back:
// objects are dicts (key order kept), arrays lists, integers int, numbers float, null None.
#include <pybind11/pybind11.h>

#include <string>

#include "spec/util/hana_json.hpp"

namespace swarmcheck::python {

pybind11::object to_python(const json_io::Json& j);
// A ValueError naming `path` (a JSON path) for a value JSON cannot hold (a set, an object, a
// non-string key).
json_io::Json from_python(pybind11::handle h, const std::string& path);

}  // namespace swarmcheck::python
