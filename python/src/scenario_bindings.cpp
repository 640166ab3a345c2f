// swarmcheck.Scenario: from the built-in default, a dict, a JSON file or keywords, validated by
// the library (the CLI's messages, as swarmcheck.InputError, a ValueError).
#include <pybind11/stl.h>

#include <set>
#include <type_traits>

#include "python/src/bindings.hpp"
#include "python/src/json_convert.hpp"
#include "python/src/scenario.hpp"
#include "spec/exploration/robot_kinds.hpp"
#include "spec/exploration/rule_set.hpp"

namespace py = pybind11;
namespace ex = swarmcheck::exploration;

namespace swarmcheck::python {
namespace {

// The keywords `run` takes as flags (--mode, --rule, ...): spelled as the flags, without "--".
const std::set<std::string>& scenario_keywords() {
  static const std::set<std::string> names{"mode", "rule", "preset", "controller", "body", "seed", "steps"};
  return names;
}

std::string text_of(const py::handle& v, const std::string& name) {
  if (!py::isinstance<py::str>(v)) throw InputError(name, "expected a string");
  return v.cast<std::string>();
}

template <class Int>
Int integer_of(const py::handle& v, const std::string& name, const char* expected) {
  if (py::isinstance<py::bool_>(v) || !py::hasattr(v, "__index__")) throw InputError(name, expected);
  const py::int_ i(py::reinterpret_borrow<py::object>(v));
  if (i < py::int_(0) && std::is_unsigned_v<Int>) throw InputError(name, expected);
  try {
    return i.cast<Int>();
  } catch (const py::cast_error&) {
    throw InputError(name, expected);
  }
}

PyScenario from_file(const std::string& path) { return {ex::load_valid_scenario(path), path}; }

PyScenario from_dict(const py::dict& d) {
  return {ex::ValidScenario(ex::scenario_from_json(from_python(d, ""))), "dict"};
}

}  // namespace

PyScenario with_keywords(PyScenario s, const py::dict& keywords) {
  if (keywords.empty()) return s;
  ex::ScenarioOverrides over;
  std::string rule, controller, body;
  for (const auto& [k, v] : keywords) {
    const std::string name = k.cast<std::string>();
    if (!scenario_keywords().contains(name)) throw py::type_error("unexpected keyword argument '" + name + "'");
    if (v.is_none()) continue;   // as if not given
    if (name == "mode") over.mode = json_io::enum_from_string<ex::Mode>(text_of(v, name), name);
    else if (name == "rule") rule = text_of(v, name);
    else if (name == "controller") controller = text_of(v, name);
    else if (name == "body") body = text_of(v, name);
    else if (name == "seed") over.seed = integer_of<uint64_t>(v, name, "expected an integer in [0, 2^64 - 1]");
    else if (name == "steps") over.max_steps = integer_of<int64_t>(v, name, "expected an integer");
    else if (name == "preset") {
      const std::string p = text_of(v, name);
      const ex::Preset* preset = ex::find_preset(p);
      if (!preset) {
        std::string names;
        for (const auto& row : ex::kPresets) names += (names.empty() ? "" : "|") + std::string(row.name);
        throw InputError(name, "expected one of " + names + ", got \"" + p + "\"");
      }
      over.rule = preset->rule;
      over.controller = preset->controller;
      over.body = preset->body;
    }
  }
  // --rule, --controller and --body beside --preset override the preset's (robot_options.hpp).
  if (!rule.empty()) over.rule = json_io::enum_from_string<ex::RuleSet>(rule, "rule");
  if (!controller.empty()) over.controller = json_io::enum_from_string<ex::ControllerKind>(controller, "controller");
  if (!body.empty()) over.body = json_io::enum_from_string<ex::BodyKind>(body, "body");
  try {
    return {ex::with_overrides(std::move(s.valid), over), s.where};
  } catch (const InputError& e) {   // the message of `run`'s command-line overrides
    throw InputError(s.where + " with the keyword overrides: " + e.where(),
                     std::string(e.what()).substr(e.where().size() + 2));
  }
}

PyScenario scenario_from(const py::handle& scenario, const py::dict& keywords) {
  if (scenario.is_none()) return with_keywords({ex::ValidScenario(ex::default_scenario()), "default scenario"}, keywords);
  if (py::isinstance<PyScenario>(scenario)) return with_keywords(scenario.cast<PyScenario>(), keywords);
  if (py::isinstance<py::dict>(scenario)) return with_keywords(from_dict(scenario.cast<py::dict>()), keywords);
  const py::object fspath = py::module_::import("os").attr("fspath");
  if (py::isinstance<py::str>(scenario) || py::hasattr(scenario, "__fspath__"))
    return with_keywords(from_file(fspath(scenario).cast<std::string>()), keywords);
  throw py::type_error("scenario: expected None, a Scenario, a dict or a path to a JSON file");
}

void bind_scenario(py::module_& m) {
  py::class_<PyScenario>(m, "Scenario", R"(An exploration scenario, validated by swarmcheck's reader.

Scenario(source=None, **keywords): source is None (the built-in thesis set-up), a dict with the
keys of a scenario file, a path to a scenario JSON file, or another Scenario; keywords are the
`swarmcheck run` flags that change a scenario: mode, rule, preset, controller, body, seed, steps.
Bad input raises swarmcheck.InputError (a ValueError) with the CLI's message, naming the file and
JSON path.)")
      .def(py::init([](const py::object& source, const py::kwargs& kw) { return scenario_from(source, kw); }),
           py::arg("source") = py::none())
      .def_static("from_file", [](const py::object& path) { return scenario_from(path, py::dict()); }, py::arg("path"),
                  "A scenario file (JSON), read and validated as `swarmcheck run FILE` does.")
      .def_static("from_dict", [](const py::dict& d) { return scenario_from(d, py::dict()); }, py::arg("d"),
                  "A scenario from a dict with the keys of a scenario file.")
      .def("replace", [](const PyScenario& s, const py::kwargs& kw) { return with_keywords(s, kw); },
           "A copy with the keywords (mode, rule, preset, controller, body, seed, steps) applied.")
      .def("to_dict", [](const PyScenario& s) { return to_python(json_io::to_json(s.valid.get())); },
           "The scenario as a dict (every key, defaults included).")
      .def_property_readonly("name", [](const PyScenario& s) { return s.where; },
                             "Where it came from: 'default scenario', the file's path, or 'dict'.")
      .def_property_readonly("map_size", [](const PyScenario& s) { return s.valid.get().map_size; }, "Cells per side.")
      .def_property_readonly("robots", [](const PyScenario& s) { return s.valid.get().robots.size(); }, "Number of robots.")
      .def_property_readonly("rule", [](const PyScenario& s) { return json_io::enum_to_string(s.valid.get().rule); }, "The rule set.")
      .def_property_readonly("mode", [](const PyScenario& s) { return json_io::enum_to_string(s.valid.get().mode); }, "abstract or cosim.")
      .def_property_readonly("seed", [](const PyScenario& s) { return s.valid.get().seed; }, "The run's one seed.")
      .def_property_readonly("max_steps", [](const PyScenario& s) { return s.valid.get().max_steps; }, "Master steps at most.")
      .def("__repr__", [](const PyScenario& s) {
        const ex::Scenario& v = s.valid.get();
        return "<swarmcheck.Scenario " + s.where + ": map " + std::to_string(v.map_size) + ", " +
               std::to_string(v.robots.size()) + " robots, rule " + json_io::enum_to_string(v.rule) + ", mode " +
               json_io::enum_to_string(v.mode) + ">";
      });

  std::vector<std::string> rules, controllers, bodies, presets;
  for (const auto& row : ex::kRuleSets) rules.emplace_back(row.name);
  for (const auto& row : ex::kControllers) controllers.emplace_back(row.name);
  for (const auto& row : ex::kBodies) bodies.emplace_back(row.name);
  for (const auto& row : ex::kPresets) presets.emplace_back(row.name);
  m.attr("RULES") = py::tuple(py::cast(rules));
  m.attr("CONTROLLERS") = py::tuple(py::cast(controllers));
  m.attr("BODIES") = py::tuple(py::cast(bodies));
  m.attr("PRESETS") = py::tuple(py::cast(presets));
  m.attr("MODES") = py::make_tuple("abstract", "cosim");
}

}  // namespace swarmcheck::python
