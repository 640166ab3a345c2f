#include "impl/dse/objectives.hpp"

#include <array>
#include <cmath>

namespace swarmcheck::dse {

double student_t_975(int32_t dof) {
  static constexpr std::array<double, 30> kTable{
      12.706204736, 4.302652730, 3.182446305, 2.776445105, 2.570581836, 2.446911851, 2.364624252,
      2.306004135, 2.262157163, 2.228138852, 2.200985160, 2.178812830, 2.160368656, 2.144786688,
      2.131449546, 2.119905299, 2.109815578, 2.100922040, 2.093024054, 2.085963447, 2.079613845,
      2.073873068, 2.068657610, 2.063898562, 2.059538553, 2.055529439, 2.051830516, 2.048407142,
      2.045229642, 2.042272456};
  if (dof < 1) return 0;
  if (dof <= 30) return kTable[static_cast<std::size_t>(dof - 1)];
  // Cornish-Fisher expansion around z = 1.959963985 (error < 1e-5 for dof > 30).
  const double z = 1.959963984540054, v = dof;
  const double z3 = z * z * z, z5 = z3 * z * z, z7 = z5 * z * z;
  return z + (z3 + z) / (4 * v) + (5 * z5 + 16 * z3 + 3 * z) / (96 * v * v) +
         (3 * z7 + 19 * z5 + 17 * z3 - 15 * z) / (384 * v * v * v);
}

std::vector<ObjectiveValue> objective_values(const DseConfig& c, const PointRuns& p) {
  std::vector<ObjectiveValue> out;
  for (const Objective& o : c.objectives) {
    ObjectiveValue v;
    v.present = !p.runs.empty();
    for (const RunOutputs& r : p.runs) {
      double x = 0;
      if (o.column.series == Series::completion_step) {
        if (!r.completion_step) { v.present = false; break; }
        x = static_cast<double>(*r.completion_step);
      } else {
        const Aggregate* a = r.column(o.column.name);
        if (!a) { v.present = false; break; }
        x = o.function == Function::max ? a->max : o.function == Function::min ? a->min : a->mean;
      }
      v.runs.push_back(x);
    }
    if (v.present) {
      double sum = 0;
      for (const double x : v.runs) sum += x;
      const double n = static_cast<double>(v.runs.size());
      v.mean = sum / n;
      if (v.runs.size() >= 2) {
        double ss = 0;
        for (const double x : v.runs) ss += (x - v.mean) * (x - v.mean);
        const double sd = std::sqrt(ss / (n - 1));
        v.ci95 = student_t_975(static_cast<int32_t>(v.runs.size()) - 1) * sd / std::sqrt(n);
      }
    } else {
      v.runs.clear();
    }
    out.push_back(std::move(v));
  }
  return out;
}

}  // namespace swarmcheck::dse
