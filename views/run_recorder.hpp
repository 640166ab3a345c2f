#pragma once
// What `swarmcheck run` records beside its trace: the field records of `--trace-field K`
// (spec/exploration/trace_field.hpp) and the robots' paths for `--svg FILE`. run_verb calls
// observe() after step 0 and after every step, and finish() once at the end.
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "conformance/exploration/engine.hpp"
#include "spec/exploration/trace_field.hpp"
#include "spec/util/hana_json.hpp"

namespace swarmcheck::views {

struct RunRecorderOptions {
  int64_t field_every = 0;   // 0: no field records
  std::string svg_path;      // empty: no picture
  std::string scenario_name; // for the picture's title
};

class RunRecorder {
 public:
  // `trace` receives the field records (it must be the trace's stream when field_every > 0).
  RunRecorder(const swarmcheck::exploration::Scenario& s, RunRecorderOptions o, std::ostream* trace);

  // The trace header, raised to format 2 with "field_every" when field records are written.
  json_io::Json header(json_io::Json h) const;
  void observe(const conformance::exploration::Simulation& sim);
  // Writes the picture (atomically) if asked for.
  void finish(const conformance::exploration::Simulation& sim);

 private:
  swarmcheck::exploration::Scenario scenario_;
  RunRecorderOptions options_;
  std::ostream* trace_;
  int64_t path_every_;   // record() is O(cells): on big maps the paths are sampled
  std::vector<std::vector<swarmcheck::exploration::Point_m>> paths_;
};

// The whole grid of a simulation at its current step.
swarmcheck::exploration::FieldSnapshot field_snapshot(const conformance::exploration::Simulation& sim,
                                                      const swarmcheck::exploration::Scenario& s);

}  // namespace swarmcheck::views
