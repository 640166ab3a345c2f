#pragma once
// A sweep's results: every design point in a fixed order (the full factorial's, or the genetic
// search's order of first evaluation) with its objective values, its constraint status, its
// Pareto rank and whether it is on the front. They depend only on the configuration, the base
// scenario and the runs' outputs: never on threads, ranks or resumption.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "impl/dse/design_space.hpp"
#include "impl/dse/evaluate.hpp"
#include "impl/dse/objectives.hpp"

namespace swarmcheck::dse {

// What the sweep knows of a point.
struct PointOutcome {
  Genome genome;
  int32_t generation = 0;                      // genetic search: first evaluated in; else 0
  int32_t violated_parameter_constraint = -1;  // >= 0: excluded, never run
  std::optional<PointRuns> runs;
};

struct PointResult {
  Genome genome;
  int32_t generation = 0;
  int32_t replicates = 0;                 // runs behind the objective values (0 when not run)
  std::vector<ObjectiveValue> objectives;
  std::string status;                     // "ok", or why the point is not ranked
  bool feasible = false;                  // ran, every objective present, constraints hold
  int32_t rank = 0;                       // Pareto rank, 1 = front; 0 when not ranked
  bool front = false;
};

struct DseResults {
  std::vector<PointResult> points;
  std::vector<std::size_t> front;   // indices into points, in point order
  int32_t generations = 0;          // genetic search: generations run
};

DseResults rank_outcomes(const DesignSpace& space, const std::vector<PointOutcome>& outcomes);

}  // namespace swarmcheck::dse
