// The library timed alone, in this process, for python/bench/overhead.py: what a Python call adds
// is the Python figure minus these (the same scenario, the same machine, one run).
#include <chrono>

#include "python/src/bindings.hpp"
#include "python/src/scenario.hpp"
#include "spec/exploration/reachability.hpp"
#include "swarmcheck/exploration.hpp"
#include "swarmcheck/run_report.hpp"

namespace py = pybind11;
namespace ex = swarmcheck::exploration;

namespace swarmcheck::python {

void bind_overhead(py::module_& m) {
  m.def(
      "_library_run_seconds",
      [](const py::object& scenario, int64_t stall_window, int32_t threads, const py::kwargs& kw) {
        const PyScenario s = scenario_from(scenario, kw);
        py::gil_scoped_release release;
        // As swarmcheck.run(): construction, reachability, the loop and the report.
        const auto t0 = std::chrono::steady_clock::now();
        ex::Exploration run(s.valid, ex::ExplorationOptions{.threads = threads});
        const ex::RunEnd end = ex::run_to_end(run, ex::reachability(s.valid.get()), stall_window, [](const auto&, bool) {});
        const json_io::Json j = ex::run_report(run, end, "impl");
        const auto t1 = std::chrono::steady_clock::now();
        return std::make_pair(std::chrono::duration<double>(t1 - t0).count(), j["steps"].get<int64_t>());
      },
      py::arg("scenario") = py::none(), py::kw_only(), py::arg("stall_window") = 100000, py::arg("threads") = 0,
      "(seconds, steps) of one run through the C++ library alone, as swarmcheck.run does it (for the overhead "
      "figures).");
  m.def(
      "_library_step_seconds",
      [](const py::object& scenario, int64_t n, int32_t threads, const py::kwargs& kw) {
        const PyScenario s = scenario_from(scenario, kw);
        py::gil_scoped_release release;
        ex::Exploration run(s.valid, ex::ExplorationOptions{.threads = threads});
        int64_t done = 0;
        const auto t0 = std::chrono::steady_clock::now();
        for (; done < n && !run.done(); ++done) run.step();
        const auto t1 = std::chrono::steady_clock::now();
        return std::make_pair(std::chrono::duration<double>(t1 - t0).count(), done);
      },
      py::arg("scenario") = py::none(), py::kw_only(), py::arg("n") = 1000, py::arg("threads") = 0,
      "(seconds, steps) of n library steps in a C++ loop, from a new simulation (for the overhead figures).");
}

}  // namespace swarmcheck::python
