#include "python/src/json_convert.hpp"

#include <pybind11/stl.h>

#include "spec/util/input_error.hpp"

namespace py = pybind11;

namespace swarmcheck::python {

py::object to_python(const json_io::Json& j) {
  switch (j.type()) {
    case json_io::Json::value_t::null: return py::none();
    case json_io::Json::value_t::boolean: return py::bool_(j.get<bool>());
    case json_io::Json::value_t::number_integer: return py::int_(j.get<int64_t>());
    case json_io::Json::value_t::number_unsigned: return py::int_(j.get<uint64_t>());
    case json_io::Json::value_t::number_float: return py::float_(j.get<double>());
    case json_io::Json::value_t::string: return py::str(j.get_ref<const std::string&>());
    case json_io::Json::value_t::array: {
      py::list out;
      for (const auto& v : j) out.append(to_python(v));
      return out;
    }
    case json_io::Json::value_t::object: {
      py::dict out;
      for (const auto& [k, v] : j.items()) out[py::str(k)] = to_python(v);
      return out;
    }
    default: return py::none();   // binary and discarded: never produced by the library
  }
}

json_io::Json from_python(py::handle h, const std::string& path) {
  if (h.is_none()) return nullptr;
  if (py::isinstance<py::bool_>(h)) return h.cast<bool>();   // before int: bool is an int
  if (py::isinstance<py::int_>(h)) {
    if (h.cast<py::int_>() < py::int_(0)) return h.cast<int64_t>();
    return h.cast<uint64_t>();
  }
  if (py::isinstance<py::float_>(h)) return h.cast<double>();
  if (py::isinstance<py::str>(h)) return h.cast<std::string>();
  if (py::isinstance<py::dict>(h)) {
    json_io::Json out = json_io::Json::object();
    for (const auto& [k, v] : h.cast<py::dict>()) {
      if (!py::isinstance<py::str>(k)) throw InputError(path, "expected string keys (JSON objects have no other)");
      const std::string key = k.cast<std::string>();
      out[key] = from_python(v, json_io::join_key(path, key));
    }
    return out;
  }
  if (py::isinstance<py::list>(h) || py::isinstance<py::tuple>(h)) {
    json_io::Json out = json_io::Json::array();
    std::size_t i = 0;
    for (const auto& v : h) out.push_back(from_python(v, json_io::join_index(path, i++)));
    return out;
  }
  // NumPy scalars and other numbers: through float or int if they convert.
  if (py::hasattr(h, "__index__")) return from_python(py::int_(py::reinterpret_borrow<py::object>(h)), path);
  if (py::hasattr(h, "__float__")) return py::float_(py::reinterpret_borrow<py::object>(h)).cast<double>();
  throw InputError(path, "expected a JSON value (dict, list, str, int, float, bool or None), got " +
                             std::string(py::str(py::type::handle_of(h).attr("__name__"))));
}

}  // namespace swarmcheck::python
