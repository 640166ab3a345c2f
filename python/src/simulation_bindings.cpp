// swarmcheck.Simulation and swarmcheck.run(): the library's exploration, in process.
#include <pybind11/numpy.h>
#include <fmt/format.h>
#include <pybind11/stl.h>

#include "python/src/bindings.hpp"
#include "python/src/json_convert.hpp"
#include "impl/io/usable_memory.hpp"
#include "python/src/simulation.hpp"

namespace py = pybind11;
namespace ex = swarmcheck::exploration;

namespace swarmcheck::python {
namespace {

constexpr int64_t kStallWindow = 100000;   // `run --stall-window`'s default

int32_t threads_of(int64_t threads) {
  if (threads < 0 || threads > 4096) throw InputError("threads", "expected an integer in [0, 4096] (0: every core)");
  return static_cast<int32_t>(threads);
}

// memory_limit: None for the CLI's default (3/4 of the memory this process may use), 0 for none.
std::uint64_t memory_limit_of(const py::object& limit) {
  if (limit.is_none()) return impl::io::default_memory_limit();
  if (py::isinstance<py::bool_>(limit) || !py::isinstance<py::int_>(limit) || limit.cast<py::int_>() < py::int_(0))
    throw InputError("memory_limit", "expected a number of bytes >= 0 (0: no limit), or None for the default");
  return limit.cast<std::uint64_t>();
}

void check_stall_window(int64_t w) {
  if (w < 0) throw InputError("stall_window", "expected a number of steps >= 0 (0: never stop early)");
}

// A read-only array over `data`, kept alive by `owner`.
template <class T>
py::array read_only_view(const T* data, std::vector<py::ssize_t> shape, const py::handle& owner) {
  std::vector<py::ssize_t> strides(shape.size());
  py::ssize_t stride = sizeof(T);
  for (std::size_t k = shape.size(); k-- > 0;) {
    strides[k] = stride;
    stride *= shape[k];
  }
  py::array a(py::dtype::of<T>(), shape, strides, data, owner);
  a.attr("flags").attr("writeable") = false;
  return a;
}

py::array_t<double> poses_of(const ex::Exploration& e) {
  const auto bodies = e.bodies();
  py::array_t<double> out({static_cast<py::ssize_t>(bodies.size()), py::ssize_t{3}});
  auto w = out.mutable_unchecked<2>();
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    const auto i = static_cast<py::ssize_t>(k);
    w(i, 0) = bodies[k].x_m;
    w(i, 1) = bodies[k].y_m;
    w(i, 2) = bodies[k].theta_rad;
  }
  return out;
}

py::array_t<int32_t> cells_of(const ex::Exploration& e) {
  const auto robots = e.robots();
  py::array_t<int32_t> out({static_cast<py::ssize_t>(robots.size()), py::ssize_t{2}});
  auto w = out.mutable_unchecked<2>();
  for (std::size_t k = 0; k < robots.size(); ++k) {
    w(static_cast<py::ssize_t>(k), 0) = robots[k].cell[0];
    w(static_cast<py::ssize_t>(k), 1) = robots[k].cell[1];
  }
  return out;
}

py::array_t<double> waypoints_of(const ex::Exploration& e) {
  const auto robots = e.robots();
  py::array_t<double> out({static_cast<py::ssize_t>(robots.size()), py::ssize_t{2}});
  auto w = out.mutable_unchecked<2>();
  for (std::size_t k = 0; k < robots.size(); ++k) {
    w(static_cast<py::ssize_t>(k), 0) = robots[k].waypoint[0];
    w(static_cast<py::ssize_t>(k), 1) = robots[k].waypoint[1];
  }
  return out;
}

}  // namespace

void bind_simulation(py::module_& m) {
  py::class_<PySimulation>(m, "Simulation", R"(One exploration run of the library, stepped from Python.

Simulation(scenario=None, *, threads=0, paths=True, **keywords): the scenario as
swarmcheck.Scenario takes it (None, a Scenario, a dict or a JSON file's path) and the `run`
flags as keywords (mode, rule, preset, controller, body, seed, steps). threads: 0 for every
core (the results are the same bits on any number). paths: keep the robots' paths for the
picture (_repr_svg_). memory_limit: bytes the run may take (None: the CLI's default, 3/4 of the
memory this process may use; 0: no limit); a scenario estimated past it is refused before
anything is allocated (swarmcheck.InputError). Not to be used from two threads at once.)")
      .def(py::init([](const py::object& scenario, int64_t threads, bool paths, const py::object& memory_limit,
                       const py::kwargs& kw) {
             PyScenario s = scenario_from(scenario, kw);
             require_memory(s, memory_limit_of(memory_limit));
             return std::make_unique<PySimulation>(std::move(s), threads_of(threads), paths);
           }),
           py::arg("scenario") = py::none(), py::kw_only(), py::arg("threads") = 0, py::arg("paths") = true,
           py::arg("memory_limit") = py::none())
      .def("step", &PySimulation::step, py::arg("n") = 1,
           "Do n master steps (fewer if the run is done first). Long calls release the GIL; Ctrl-C raises "
           "KeyboardInterrupt, the simulation left at the last whole step.")
      .def(
          "run", [](PySimulation& s, int64_t stall_window) {
            check_stall_window(stall_window);
            return to_python(s.run(stall_window));
          },
          py::arg("stall_window") = kStallWindow,
          "Step to the end as `swarmcheck run` does (completed, max_steps, or stalled: no newly visited cell in "
          "stall_window steps, 0 never) and return the dict `swarmcheck run --json` prints.")
      .def_property_readonly("done", [](const PySimulation& s) { return s.library().done(); },
                             "Completed (eP 100 %) or max_steps done.")
      .def_property_readonly("steps", [](const PySimulation& s) { return s.library().steps(); }, "Master steps done.")
      .def_property_readonly("planning_steps", [](const PySimulation& s) { return s.library().planning_steps(); },
                             "Steps in which the Environment chose new cells.")
      .def_property_readonly("visited", [](const PySimulation& s) { return s.library().visited(); }, "Visited free cells.")
      .def_property_readonly("free_cells", [](const PySimulation& s) { return s.library().free_cells(); }, "Free cells of the map.")
      .def_property_readonly("eP", [](const PySimulation& s) { return s.library().eP(); }, "Exploration percentage.")
      .def_property_readonly("sTime", [](const PySimulation& s) { return s.library().sTime(); }, "Simulated time, s.")
      .def_property_readonly("completion_step", [](const PySimulation& s) { return s.library().completion_step(); },
                             "The step eP reached 100 %, or None.")
      .def_property_readonly("scenario", [](const PySimulation& s) { return s.scenario(); }, "The Scenario it runs.")
      .def("state", [](const PySimulation& s) { return to_python(json_io::to_json(s.library().record())); },
           "The observable state, as one record of the JSON Lines trace: step, planning_steps, handshake, visited, "
           "free_cells, eP, sTime, pheromone_digest and per robot its cell, waypoint, body pose and controller "
           "(maneuver, on_destination_output, beta_rad, servos, target_theta_rad). O(cells).")
      .def_property_readonly("cells", [](const PySimulation& s) { return cells_of(s.library()); },
                             "The cell each robot was last moved to, int32 array (robots, 2) of [i, j] (a copy).")
      .def_property_readonly("waypoints", [](const PySimulation& s) { return waypoints_of(s.library()); },
                             "The waypoint each robot issued, float64 array (robots, 2), metres (a copy).")
      .def_property_readonly("poses", [](const PySimulation& s) { return poses_of(s.library()); },
                             "Each robot's pose, float64 array (robots, 3) of x_m, y_m, theta_rad (a copy).")
      .def_property_readonly(
          "field",
          [](py::object self) {
            PySimulation& s = self.cast<PySimulation&>();
            const auto& f = s.current_field();
            const auto n = static_cast<py::ssize_t>(s.scenario().valid.get().map_size);
            return read_only_view(f.data(), {n, n}, self);
          },
          "The pheromone field at the current step, float64 (map_size, map_size), cell (i, j) at [i, j]: a "
          "read-only view of the simulation's field buffer (no copy). The library evaluates evaporation lazily, so "
          "the buffer is brought up to date when `field` is read after a step; every view shares it.")
      .def_property_readonly(
          "visited_cells",
          [](const PySimulation& s) {
            const auto mask = s.visited_mask();
            const auto n = static_cast<py::ssize_t>(s.scenario().valid.get().map_size);
            py::array_t<bool> out({n, n});
            std::copy(mask.begin(), mask.end(), out.mutable_data());
            return out;
          },
          "Which cells are visited, bool array (map_size, map_size) (a copy).")
      .def("svg", &PySimulation::svg, "The picture of `swarmcheck run --svg` at the current step, as SVG text.")
      .def("_repr_svg_", &PySimulation::svg)
      .def("__repr__", [](const PySimulation& s) {
        const auto& e = s.library();
        return "<swarmcheck.Simulation " + s.scenario().where + ": step " + std::to_string(e.steps()) + ", eP " +
               fmt::format("{:.2f}", e.eP()) + " %" + (e.done() ? ", done" : "") + ">";
      });

  m.def(
      "run",
      [](const py::object& scenario, int64_t stall_window, int64_t threads, const py::object& memory_limit,
         const py::kwargs& kw) {
        check_stall_window(stall_window);
        PyScenario s = scenario_from(scenario, kw);
        require_memory(s, memory_limit_of(memory_limit));
        PySimulation sim(std::move(s), threads_of(threads), false);
        return to_python(sim.run(stall_window));
      },
      py::arg("scenario") = py::none(), py::kw_only(), py::arg("stall_window") = kStallWindow,
      py::arg("threads") = 0, py::arg("memory_limit") = py::none(),
      R"(One exploration run, as `swarmcheck run --json`: returns the same dict.

scenario: None (the built-in thesis set-up), a Scenario, a dict or a JSON file's path; the
keywords are the flags of `run`: mode, rule, preset, controller, body, seed, steps,
stall_window, threads, memory_limit (bytes; None: the CLI's default; 0: none). Computed by the library in this process, the GIL released; Ctrl-C raises
KeyboardInterrupt.)");
}

}  // namespace swarmcheck::python
