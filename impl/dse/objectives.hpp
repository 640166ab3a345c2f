#pragma once
// A point's objective values: each objective's internal function (max, min or mean of its
// column) per run, then over the replicates the mean and, with two or more, the half-width of
// the 95 % confidence interval of that mean (Student's t: t(0.975, n-1) * s / sqrt(n)).
#include <cstdint>
#include <optional>
#include <vector>

#include "impl/dse/config.hpp"
#include "impl/dse/evaluate.hpp"

namespace swarmcheck::dse {

struct ObjectiveValue {
  bool present = false;          // false: a run lacks the column (completion_step of an incomplete run)
  double mean = 0;
  std::optional<double> ci95;    // half-width, with two or more runs
  std::vector<double> runs;      // per replicate
};

std::vector<ObjectiveValue> objective_values(const DseConfig& c, const PointRuns& p);

// t(0.975, dof) for dof >= 1 (exact table to 30, then the normal quantile's expansion).
double student_t_975(int32_t dof);

}  // namespace swarmcheck::dse
