#include "conformance/mission/engine.hpp"

#include "model/mission/thesis_dijkstra.hpp"

namespace swarmcheck::conformance::mission {

PlannerKind planner_named(const std::string& name) {
  if (name == "exact") return PlannerKind::exact;
  if (name == "thesis") return PlannerKind::thesis;
  throw InputError("--planner", "expected exact or thesis, got \"" + name + "\"");
}

swarmcheck::mission::Plan plan(const swarmcheck::mission::Mission& m,
                               const swarmcheck::mission::PlanQuery& q, PlannerKind kind) {
  if (kind == PlannerKind::thesis) return swarmcheck::model::mission::thesis_plan(m, q);
  return swarmcheck::mission::Planner(m).plan(q);
}

}  // namespace swarmcheck::conformance::mission
