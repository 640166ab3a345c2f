#pragma once
// swarmcheck.Simulation: the library's Exploration with what Python reads of it (the state as a
// dict, the field as a NumPy view) and the robots' paths for its picture.
#include <pybind11/pybind11.h>

#include <optional>
#include <string>
#include <vector>

#include "python/src/interrupt.hpp"
#include "python/src/scenario.hpp"
#include "spec/exploration/reachability.hpp"
#include "swarmcheck/exploration.hpp"
#include "swarmcheck/run_report.hpp"

namespace swarmcheck::python {

// Refuses a scenario whose run would not fit in `limit_bytes` (0: no limit) before anything is
// allocated, with the message of `swarmcheck run`'s --memory-limit (the same estimate).
void require_memory(const PyScenario& s, std::uint64_t limit_bytes);

class PySimulation {
 public:
  PySimulation(PyScenario s, int32_t threads, bool paths);

  // n steps at most (fewer when it is done first); the GIL released, Ctrl-C polled.
  void step(int64_t n);
  // To the end as `swarmcheck run` (swarmcheck/run_report.hpp): the --json dict's Json.
  json_io::Json run(int64_t stall_window);

  const swarmcheck::exploration::Exploration& library() const { return run_; }
  const PyScenario& scenario() const { return scenario_; }
  // The field at steps(), in the buffer field views share (row i, column j at i*N + j).
  const std::vector<double>& current_field();
  std::vector<uint8_t> visited_mask() const;
  std::string svg() const;

 private:
  void after_step();   // paths
  const swarmcheck::exploration::Reachability& reach();

  PyScenario scenario_;
  swarmcheck::exploration::Exploration run_;
  std::optional<swarmcheck::exploration::Reachability> reach_;
  std::vector<double> field_;
  int64_t field_step_ = -1;
  bool record_paths_;
  int64_t path_every_;
  std::vector<std::vector<swarmcheck::exploration::Point_m>> paths_;
};

}  // namespace swarmcheck::python
