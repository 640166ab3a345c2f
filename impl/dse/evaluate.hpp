#pragma once
// Running a design point: each replicate's scenario through the library, one thread per run,
// with the output columns the objectives read reduced to min, max and mean over the run's rows
// (step 0, the initial state, included, as in an INTO-CPS results file).
//
// Columns: eP, sTime, visited, planning_steps, steps (the Environment's outputs at each step);
// completion_step (one value, absent when the run did not complete); distance and turning (the
// odometers: metres travelled and |radians| turned, summed over steps, per robot and in total).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "impl/dse/design_space.hpp"
#include "impl/dse/names.hpp"
#include "spec/exploration/types.hpp"
#include "spec/util/hana_json.hpp"

namespace swarmcheck::dse {

struct Aggregate {
  double min = 0, max = 0, mean = 0;
};

struct RunOutputs {
  uint64_t seed = 0;
  int64_t steps = 0;
  std::optional<int64_t> completion_step;
  std::vector<std::pair<std::string, Aggregate>> columns;   // by canonical column name

  const Aggregate* column(const std::string& name) const;
};

struct PointRuns {
  std::string key;                // DesignSpace::point_key
  std::vector<RunOutputs> runs;   // one per replicate, in replicate order
};

// The columns a configuration needs computed: the Environment's always, the odometers when an
// objective reads one (in total or for a robot).
std::vector<Column> needed_columns(const DseConfig& c);
bool has_columns(const PointRuns& p, const std::vector<Column>& columns);

RunOutputs run_scenario(const exploration::Scenario& s, const std::vector<Column>& columns);
PointRuns evaluate_point(const DesignSpace& space, const Genome& g, const std::vector<Column>& columns);

// The journal's and the MPI messages' form; doubles round-trip exactly.
json_io::Json to_json(const PointRuns& p);
PointRuns point_runs_from_json(const json_io::Json& j);   // throws InputError on a malformed record

}  // namespace swarmcheck::dse
