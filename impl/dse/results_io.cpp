#include "impl/dse/results_io.hpp"

#include "impl/dse/format.hpp"

namespace swarmcheck::dse {

using json_io::Json;

std::string objective_direction(const DseConfig& c, std::size_t objective) {
  for (const ParetoDimension& d : c.pareto)
    if (d.objective == objective) return d.maximise ? "+" : "-";
  return "";
}

bool any_replicated(const DseResults& r) {
  for (const PointResult& p : r.points)
    if (p.replicates >= 2) return true;
  return false;
}

std::string parameter_value_text(const DesignSpace& space, const Genome& g, std::size_t parameter) {
  return value_text(space.config().parameters[parameter].values[static_cast<std::size_t>(g[parameter])]);
}

std::string results_csv(const DesignSpace& space, const DseResults& r) {
  const DseConfig& c = space.config();
  const bool genetic = c.algorithm == Algorithm::genetic;
  const bool ci = any_replicated(r);
  std::string out = "point";
  if (genetic) out += ",generation";
  for (const SweptParameter& p : c.parameters) out += "," + csv_field(p.name);
  for (const Objective& o : c.objectives) {
    out += "," + csv_field(o.name);
    if (ci) out += "," + csv_field(o.name + "_ci95");
  }
  out += ",runs,status,rank,pareto_front\n";
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const PointResult& p = r.points[i];
    out += std::to_string(i + 1);
    if (genetic) out += "," + std::to_string(p.generation);
    for (std::size_t k = 0; k < c.parameters.size(); ++k) out += "," + csv_field(parameter_value_text(space, p.genome, k));
    for (std::size_t k = 0; k < c.objectives.size(); ++k) {
      const bool has = k < p.objectives.size() && p.objectives[k].present;
      out += "," + (has ? number_text(p.objectives[k].mean) : std::string());
      if (ci) out += "," + (has && p.objectives[k].ci95 ? number_text(*p.objectives[k].ci95) : std::string());
    }
    out += "," + std::to_string(p.replicates) + "," + csv_field(p.status) + "," +
           (p.rank > 0 ? std::to_string(p.rank) : std::string()) + "," + (p.front ? "true" : "false") + "\n";
  }
  return out;
}

Json results_json(const DesignSpace& space, const DseResults& r, const ResultsContext& ctx) {
  const DseConfig& c = space.config();
  const bool genetic = c.algorithm == Algorithm::genetic;
  Json j{{"format", "swarmcheck-dse-results"}, {"format_version", 1}, {"config", ctx.config_label},
         {"scenario", ctx.scenario_label}, {"algorithm", genetic ? "genetic" : "exhaustive"},
         {"design_space_size", space.size()}};
  if (genetic) j["generations"] = r.generations;
  Json params = Json::array();
  for (const SweptParameter& p : c.parameters) {
    Json values = Json::array();
    for (const ParameterValue& v : p.values) values.push_back(v.json);
    params.push_back(Json{{"name", p.name}, {"sets", knob_info(p.knob).scenario_key}, {"values", values}});
  }
  j["parameters"] = params;
  Json objectives = Json::array();
  for (std::size_t k = 0; k < c.objectives.size(); ++k) {
    const std::string dir = objective_direction(c, k);
    objectives.push_back(Json{{"name", c.objectives[k].name}, {"column", c.objectives[k].column_id},
                              {"function", function_name(c.objectives[k].function)},
                              {"pareto", dir.empty() ? Json(nullptr) : Json(dir)}});
  }
  j["objectives"] = objectives;
  Json points = Json::array();
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const PointResult& p = r.points[i];
    Json point{{"point", i + 1}};
    if (genetic) point["generation"] = p.generation;
    Json values = Json::object();
    for (std::size_t k = 0; k < c.parameters.size(); ++k)
      values[c.parameters[k].name] = c.parameters[k].values[static_cast<std::size_t>(p.genome[k])].json;
    point["parameters"] = values;
    point["replicates"] = p.replicates;
    Json objs = Json::object();
    for (std::size_t k = 0; k < p.objectives.size(); ++k) {
      const ObjectiveValue& v = p.objectives[k];
      objs[c.objectives[k].name] = !v.present ? Json(nullptr)
          : Json{{"mean", v.mean}, {"ci95", v.ci95 ? Json(*v.ci95) : Json(nullptr)}, {"runs", v.runs}};
    }
    point["objectives"] = p.objectives.empty() ? Json(nullptr) : objs;
    point["status"] = p.status;
    point["rank"] = p.rank > 0 ? Json(p.rank) : Json(nullptr);
    point["pareto_front"] = p.front;
    points.push_back(std::move(point));
  }
  j["points"] = points;
  Json front = Json::array();
  for (const std::size_t i : r.front) front.push_back(i + 1);
  j["pareto_front"] = front;
  return j;
}

}  // namespace swarmcheck::dse
