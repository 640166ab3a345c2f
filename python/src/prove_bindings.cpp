// swarmcheck.prove: the Z3 proof obligations, each in a forked prover under a watchdog as
// `swarmcheck prove` runs them; the dict of `prove --json` (proofs/obligations/report_json.hpp).
#include <pybind11/stl.h>

#include <optional>

#include "proofs/obligations/report_json.hpp"
#include "proofs/obligations/runner.hpp"
#include "python/src/bindings.hpp"
#include "python/src/json_convert.hpp"

namespace py = pybind11;

namespace swarmcheck::python {

void bind_prove(py::module_& m) {
  std::vector<std::string> names;
  for (const proofs::Obligation& ob : proofs::all_obligations()) names.push_back(ob.name);
  m.attr("OBLIGATIONS") = py::tuple(py::cast(names));
  m.def(
      "prove",
      [](const std::optional<std::string>& only, double timeout) {
        if (!(timeout > 0 && timeout <= 86400)) throw InputError("timeout", "expected seconds in (0, 86400]");
        std::vector<const proofs::Obligation*> selected;
        if (!only) {
          for (const proofs::Obligation& ob : proofs::all_obligations()) selected.push_back(&ob);
        } else if (const proofs::Obligation* ob = proofs::find_obligation(*only)) {
          selected.push_back(ob);
        } else {
          std::string all;
          for (const proofs::Obligation& o : proofs::all_obligations()) all += (all.empty() ? "" : ", ") + o.name;
          throw InputError("only " + *only, "no such obligation; the obligations are: " + all);
        }
        std::vector<proofs::ObligationReport> reports;
        double total = 0;
        for (const proofs::Obligation* ob : selected) {
          {
            py::gil_scoped_release release;
            reports.push_back(proofs::run_isolated(*ob, timeout, proofs::kQueryTimeoutMs));
          }
          total += reports.back().seconds;
          if (PyErr_CheckSignals() != 0) throw py::error_already_set();   // Ctrl-C between obligations
        }
        return to_python(proofs::prove_report_json(reports, total, {}));
      },
      py::arg("only") = py::none(), py::arg("timeout") = static_cast<double>(proofs::kObligationTimeoutS),
      R"(`swarmcheck prove --json`: the Z3 proof obligations (all, or the one named `only`, see
OBLIGATIONS), each in a forked prover killed after `timeout` seconds; the same dict (each
obligation's expected and actual verdict, whether it is met, its detail and assumptions).)");
}

}  // namespace swarmcheck::python
