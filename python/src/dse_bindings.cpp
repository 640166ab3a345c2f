// swarmcheck.dse: a design-space exploration over an INTO-CPS DSE configuration through the
// library (impl/dse), on threads; the results object `swarmcheck dse --json` prints
// (results.json), its points as records.
#include <pybind11/stl.h>

#include <atomic>
#include <filesystem>
#include <random>
#include <thread>

#include "impl/dse/results_io.hpp"
#include "impl/dse/sweep.hpp"
#include "python/src/bindings.hpp"
#include "python/src/json_convert.hpp"
#include "python/src/scenario.hpp"

namespace py = pybind11;
namespace fs = std::filesystem;
namespace dse = swarmcheck::dse;

namespace swarmcheck::python {
namespace {

// A journal the sweep needs, when the caller keeps none: a fresh folder under the temporary
// directory, removed afterwards whatever happens.
class ScratchJournal {
 public:
  ScratchJournal() {
    std::random_device rd;
    dir_ = fs::temp_directory_path() / ("swarmcheck-python-dse-" + std::to_string(rd()) + std::to_string(rd()));
    fs::create_directories(dir_);
  }
  ~ScratchJournal() {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  ScratchJournal(const ScratchJournal&) = delete;
  ScratchJournal& operator=(const ScratchJournal&) = delete;
  std::string path() const { return (dir_ / "journal.jsonl").string(); }

 private:
  fs::path dir_;
};

}  // namespace

void bind_dse(py::module_& m) {
  m.def(
      "dse",
      [](const py::object& config, const py::object& scenario, int64_t threads, const py::object& journal,
         const py::kwargs& kw) {
        for (const auto& [k, v] : kw) {
          const std::string name = k.cast<std::string>();
          if (name != "preset" && name != "controller" && name != "body")
            throw py::type_error("unexpected keyword argument '" + name + "'");
        }
        if (threads < 0 || threads > 4096) throw InputError("threads", "expected an integer in [0, 4096] (0: every core)");
        const py::object fspath = py::module_::import("os").attr("fspath");
        const std::string config_path = fspath(config).cast<std::string>();
        const dse::DseConfig cfg = dse::load_dse_config(config_path);
        const PyScenario base = scenario_from(scenario, kw);
        const dse::DesignSpace space(cfg, base.valid.get());
        dse::check_design_space(space);
        std::optional<ScratchJournal> scratch;
        if (journal.is_none()) scratch.emplace();
        const std::string journal_path = scratch ? scratch->path() : fspath(journal).cast<std::string>();
        std::atomic<bool> stop{false};
        bool interrupted = false;
        dse::SweepOutcome outcome;
        {
          py::gil_scoped_release release;
          dse::ThreadExecutor executor(space, dse::needed_columns(cfg), static_cast<int32_t>(threads), &stop);
          // Ctrl-C as `swarmcheck dse`'s first one: the points in flight finish (kept in the journal),
          // then KeyboardInterrupt.
          dse::SweepOptions options{journal_path, &stop, [&](const dse::SweepProgress&) {
                                      py::gil_scoped_acquire gil;
                                      if (!interrupted && PyErr_CheckSignals() != 0) {
                                        interrupted = true;
                                        stop = true;
                                      }
                                    }};
          outcome = dse::run_sweep(space, executor, options);
        }
        if (interrupted) throw py::error_already_set();
        dse::DseResults results = dse::rank_outcomes(space, outcome.points);
        results.generations = outcome.generations;
        const dse::ResultsContext ctx{config_path, base.where};
        return to_python(dse::results_json(space, results, ctx));
      },
      py::arg("config"), py::arg("scenario") = py::none(), py::kw_only(), py::arg("threads") = 0,
      py::arg("journal") = py::none(),
      R"(`swarmcheck dse CONFIG --json`: the design points of an INTO-CPS DSE configuration (.dse.json) run
on the base scenario (None, a Scenario, a dict or a JSON file's path; keywords preset,
controller, body as the flags), ranked; returns the results object (results.json), whose
"points" are one record a design point. threads: points in parallel (0: every core); journal:
a path to keep the runs in and resume from (default: a temporary one). Ctrl-C finishes the
points in flight, then raises KeyboardInterrupt.)");
}

}  // namespace swarmcheck::python
