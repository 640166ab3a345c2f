#include "impl/dse/results.hpp"

#include "impl/dse/pareto.hpp"

namespace swarmcheck::dse {
namespace {

// The status of a point that ran: the first objective missing or constraint violated, or "ok".
std::string status_of(const DesignSpace& space, const PointOutcome& o, const std::vector<ObjectiveValue>& values) {
  const DseConfig& c = space.config();
  for (std::size_t k = 0; k < c.objectives.size(); ++k)
    if (!values[k].present) return "no value for " + c.objectives[k].name + " (a run did not complete)";
  const NameValues names = [&](const std::string& name) {
    for (std::size_t k = 0; k < c.objectives.size(); ++k)
      if (c.objectives[k].name == name) return Value::of_number(values[k].mean);
    return space.knob_value(o.genome, *knob_of(name));
  };
  for (const Constraint& k : c.objective_constraints)
    if (!k.expression.evaluate(names)) return "violates " + k.path;
  return "ok";
}

}  // namespace

DseResults rank_outcomes(const DesignSpace& space, const std::vector<PointOutcome>& outcomes) {
  const DseConfig& c = space.config();
  DseResults r;
  std::vector<RankInput> ranking;
  for (const PointOutcome& o : outcomes) {
    PointResult p;
    p.genome = o.genome;
    p.generation = o.generation;
    if (o.violated_parameter_constraint >= 0) {
      p.status = "excluded by " + c.parameter_constraints[static_cast<std::size_t>(o.violated_parameter_constraint)].path;
    } else if (!o.runs) {
      p.status = "not run";
    } else {
      p.replicates = static_cast<int32_t>(o.runs->runs.size());
      p.objectives = objective_values(c, *o.runs);
      p.status = status_of(space, o, p.objectives);
      p.feasible = p.status == "ok";
    }
    RankInput in;
    in.ranked = p.feasible && !c.pareto.empty();
    for (const ParetoDimension& d : c.pareto) {
      const double v = in.ranked ? p.objectives[d.objective].mean : 0;
      in.values.push_back(d.maximise ? v : -v);
    }
    ranking.push_back(std::move(in));
    r.points.push_back(std::move(p));
  }
  const std::vector<int32_t> ranks = pareto_ranks(ranking);
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    r.points[i].rank = ranks[i];
    r.points[i].front = ranks[i] == 1;
    if (r.points[i].front) r.front.push_back(i);
  }
  return r;
}

}  // namespace swarmcheck::dse
