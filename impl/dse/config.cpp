#include "impl/dse/config.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include "spec/exploration/scenario.hpp"
#include "spec/exploration/types.hpp"
#include "spec/util/input_file.hpp"
#include "spec/util/json_text.hpp"

namespace swarmcheck::dse {
namespace {

using json_io::Json;

std::string quoted_key(const std::string& parent, const std::string& key) {
  return parent + "[\"" + key + "\"]";
}

void only_keys(const Json& j, const std::string& path, std::initializer_list<const char*> keys) {
  if (!j.is_object()) throw InputError(path.empty() ? "(top level)" : path, "expected an object, got " + json_io::type_name(j));
  std::string list;
  for (const char* k : keys) list += (list.empty() ? "" : ", ") + std::string(k);
  for (auto it = j.begin(); it != j.end(); ++it) {
    bool known = false;
    for (const char* k : keys) known = known || it.key() == k;
    if (!known) throw InputError(path.empty() ? it.key() : path + "." + it.key(), "unknown key (expected one of: " + list + ")");
  }
}

// j[key], or null when j lacks it.
const Json& member(const Json& j, const char* key) {
  static const Json null_json;
  const auto it = j.find(key);
  return it == j.end() ? null_json : *it;
}

double integral_number(const Json& v, const std::string& path, double lo, double hi, const std::string& what) {
  if (!v.is_number()) throw InputError(path, "expected " + what + ", got " + json_io::type_name(v));
  const double x = v.get<double>();
  if (!(std::isfinite(x) && x == std::floor(x) && x >= lo && x <= hi)) throw InputError(path, "expected " + what + ", got " + v.dump());
  return x;
}

ParameterValue parameter_value(Knob knob, const Json& v, const std::string& path) {
  ParameterValue out;
  out.json = v;
  const KnobInfo& info = knob_info(knob);
  if (info.type == ValueType::text) {
    if (!v.is_string()) throw InputError(path, "expected a string (" + std::string(info.meaning) + "), got " + json_io::type_name(v));
    out.text = v.get<std::string>();
    if (knob == Knob::rule) (void)json_io::enum_from_string<exploration::RuleSet>(out.text, path);
    if (knob == Knob::mode) (void)json_io::enum_from_string<exploration::Mode>(out.text, path);
    if (knob == Knob::controller) (void)json_io::enum_from_string<exploration::ControllerKind>(out.text, path);
    if (knob == Knob::body) (void)json_io::enum_from_string<exploration::BodyKind>(out.text, path);
    return out;
  }
  constexpr double kExact = 9007199254740992.0;   // 2^53: integers beyond are not exact in a double
  switch (knob) {
    case Knob::replicates: out.number = integral_number(v, path, 1, kReplicatesMax, "an integer in [1, " + std::to_string(kReplicatesMax) + "]"); break;
    case Knob::robot_count: out.number = integral_number(v, path, 1, static_cast<double>(exploration::kRobotsMax), "an integer >= 1"); break;
    case Knob::obstacle_count: out.number = integral_number(v, path, 0, kExact, "an integer >= 0"); break;
    case Knob::seed: out.number = integral_number(v, path, 0, kExact, "an integer in [0, 2^53]"); break;
    case Knob::max_steps: out.number = integral_number(v, path, 0, static_cast<double>(exploration::kStepsMax), "an integer in [0, 2^31 - 1]"); break;
    case Knob::map_size: out.number = integral_number(v, path, 1, exploration::kMapSizeMax, "an integer in [1, " + std::to_string(exploration::kMapSizeMax) + "]"); break;
    case Knob::s_range: out.number = integral_number(v, path, 1, exploration::kRangeMax, "an integer in [1, " + std::to_string(exploration::kRangeMax) + "]"); break;
    default:
      if (!v.is_number() || !std::isfinite(v.get<double>())) throw InputError(path, "expected a finite number, got " + (v.is_number() ? v.dump() : json_io::type_name(v)));
      out.number = v.get<double>();
      if (knob == Knob::obstacle_density && !(out.number >= 0 && out.number < 1))
        throw InputError(path, "expected a share in [0, 1), got " + v.dump());
  }
  return out;
}

std::vector<SweptParameter> parse_parameters(const Json& j) {
  if (!j.is_object() || j.empty()) throw InputError("parameters", "expected an object with at least one parameter (name: list of values)");
  std::vector<SweptParameter> out;
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string path = quoted_key("parameters", it.key());
    const auto knob = knob_of(it.key());
    if (!knob) throw InputError(path, "unknown parameter (known: " + known_parameter_names() + "; INTO-CPS names as {Environment}.EnvironmentInstance.NAME)");
    for (const SweptParameter& p : out)
      if (p.knob == *knob) throw InputError(path, "sets the same thing as parameters[\"" + p.name + "\"]");
    if ((*knob == Knob::obstacle_count || *knob == Knob::obstacle_density))
      for (const SweptParameter& p : out)
        if (p.knob == Knob::obstacle_count || p.knob == Knob::obstacle_density)
          throw InputError(path, "nObstacles and obstacleDensity cannot both be swept");
    if (!it.value().is_array() || it.value().empty()) throw InputError(path, "expected a non-empty list of values");
    SweptParameter p{it.key(), *knob, {}};
    for (std::size_t k = 0; k < it.value().size(); ++k) {
      const std::string vpath = json_io::join_index(path, k);
      p.values.push_back(parameter_value(*knob, it.value()[k], vpath));
      for (std::size_t e = 0; e < k; ++e)
        if (p.values[e].json == p.values[k].json) throw InputError(vpath, "repeats the value at [" + std::to_string(e) + "]");
    }
    out.push_back(std::move(p));
  }
  return out;
}

std::vector<Constraint> parse_constraints(const Json& j, const std::string& key, const NameTypes& types,
                                          const std::string& file, const std::string& known) {
  std::vector<Constraint> out;
  if (j.is_null()) return out;
  if (!j.is_array()) throw InputError(key, "expected a list of expressions (strings)");
  for (std::size_t k = 0; k < j.size(); ++k) {
    const std::string path = json_io::join_index(key, k);
    if (!j[k].is_string()) throw InputError(path, "expected an expression (a string), got " + json_io::type_name(j[k]));
    out.push_back(Constraint{path, Expression::parse(j[k].get<std::string>(), types, file + ": " + path, known)});
  }
  return out;
}

std::vector<Objective> parse_objectives(const Json& j) {
  only_keys(j, "objectiveDefinitions", {"externalScripts", "internalFunctions"});
  if (j.contains("externalScripts") && !(j["externalScripts"].is_object() && j["externalScripts"].empty()))
    throw InputError("objectiveDefinitions.externalScripts",
                     "external scripts are not supported (swarmcheck computes objectives itself): expected {} and "
                     "objectives in internalFunctions");
  if (!j.contains("internalFunctions") || !j["internalFunctions"].is_object() || j["internalFunctions"].empty())
    throw InputError("objectiveDefinitions.internalFunctions", "expected an object with at least one objective");
  std::vector<Objective> out;
  const Json& f = j["internalFunctions"];
  for (auto it = f.begin(); it != f.end(); ++it) {
    const std::string path = quoted_key("objectiveDefinitions.internalFunctions", it.key());
    only_keys(it.value(), path, {"columnID", "objectiveType"});
    if (knob_of(it.key())) throw InputError(path, "an objective may not have a parameter's name");
    const Json& col = member(it.value(), "columnID");
    if (!col.is_string()) throw InputError(path + ".columnID", "expected a column name (" + known_column_names() + ")");
    const auto column = column_of(col.get<std::string>());
    if (!column) throw InputError(path + ".columnID", "unknown column \"" + col.get<std::string>() + "\" (known: " + known_column_names() + ")");
    const Json& type = member(it.value(), "objectiveType");
    const std::string t = type.is_string() ? type.get<std::string>() : "";
    if (t != "max" && t != "min" && t != "mean") throw InputError(path + ".objectiveType", "expected \"max\", \"min\" or \"mean\", got " + (type.is_null() ? "nothing" : type.dump()));
    out.push_back(Objective{it.key(), col.get<std::string>(), *column, t == "max" ? Function::max : t == "min" ? Function::min : Function::mean});
  }
  return out;
}

std::vector<ParetoDimension> parse_ranking(const Json& j, const std::vector<Objective>& objectives) {
  std::vector<ParetoDimension> out;
  if (j.is_null()) return out;
  only_keys(j, "ranking", {"pareto"});
  if (!j.contains("pareto")) return out;
  const Json& p = j["pareto"];
  if (!p.is_object()) throw InputError("ranking.pareto", "expected an object {objective: \"+\" | \"-\"}");
  for (auto it = p.begin(); it != p.end(); ++it) {
    const std::string path = quoted_key("ranking.pareto", it.key());
    std::size_t index = objectives.size();
    for (std::size_t k = 0; k < objectives.size(); ++k)
      if (objectives[k].name == it.key()) index = k;
    if (index == objectives.size()) throw InputError(path, "not an objective of objectiveDefinitions.internalFunctions");
    if (!(it.value() == "+" || it.value() == "-")) throw InputError(path, "expected \"+\" (maximise) or \"-\" (minimise), got " + it.value().dump());
    out.push_back(ParetoDimension{index, it.value() == "+"});
  }
  return out;
}

int32_t bounded_int(const Json& j, const char* key, int32_t lo, int32_t hi, int32_t fallback) {
  if (!j.contains(key)) return fallback;
  const std::string path = std::string("algorithm.") + key;
  return static_cast<int32_t>(integral_number(j[key], path, lo, hi, "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]"));
}

GeneticOptions parse_genetic(const Json& j) {
  GeneticOptions g;
  g.initial_population = bounded_int(j, "initialPopulation", 2, 10000, g.initial_population);
  g.max_generations_without_improvement = bounded_int(j, "maxGenerationsWithoutImprovement", 1, 1000, g.max_generations_without_improvement);
  g.max_generations = bounded_int(j, "maxGenerations", 1, 10000, g.max_generations);
  if (j.contains("seed")) g.seed = static_cast<uint64_t>(integral_number(j["seed"], "algorithm.seed", 0, 9007199254740992.0, "an integer in [0, 2^53]"));
  if (j.contains("mutationProbability")) {
    const Json& m = j["mutationProbability"];
    if (!m.is_number() || !(m.get<double>() >= 0 && m.get<double>() <= 100))
      throw InputError("algorithm.mutationProbability", "expected a percentage in [0, 100], got " + m.dump());
    g.mutation_probability = m.get<double>() / 100;
  }
  if (j.contains("initialPopulationDistribution")) {
    const Json& d = j["initialPopulationDistribution"];
    if (!(d == "random" || d == "uniform")) throw InputError("algorithm.initialPopulationDistribution", "expected \"random\" or \"uniform\", got " + d.dump());
    g.distribution = d == "random" ? InitialDistribution::random : InitialDistribution::uniform;
  }
  if (j.contains("parentSelectionStrategy")) {
    const Json& s = j["parentSelectionStrategy"];
    if (!(s == "random" || s == "algorithmObjectiveSpace"))
      throw InputError("algorithm.parentSelectionStrategy", "expected \"random\" or \"algorithmObjectiveSpace\", got " + s.dump());
    g.selection = s == "random" ? ParentSelection::random : ParentSelection::objective_space;
  }
  return g;
}

void parse_algorithm(const Json& j, DseConfig& c) {
  if (j.is_null()) return;
  if (!j.is_object() || !j.contains("type")) throw InputError("algorithm", "expected an object with \"type\": \"exhaustive\" or \"genetic\"");
  if (j["type"] == "exhaustive") {
    only_keys(j, "algorithm", {"type"});
  } else if (j["type"] == "genetic") {
    only_keys(j, "algorithm", {"type", "initialPopulation", "initialPopulationDistribution", "mutationProbability",
                               "parentSelectionStrategy", "maxGenerationsWithoutImprovement", "maxGenerations", "seed"});
    c.algorithm = Algorithm::genetic;
    c.genetic = parse_genetic(j);
  } else {
    throw InputError("algorithm.type", "expected \"exhaustive\" or \"genetic\", got " + j["type"].dump());
  }
}

DseConfig config_from_json(const Json& j, const std::string& file) {
  only_keys(j, "", {"algorithm", "objectiveConstraints", "objectiveDefinitions", "parameterConstraints", "parameters", "ranking", "scenarios"});
  if (j.contains("scenarios") && !(j["scenarios"].is_array() && j["scenarios"].empty()))
    throw InputError("scenarios", "expected [] (INTO-CPS multi-model scenarios do not apply: the base scenario is --scenario)");
  DseConfig c;
  c.file = file;
  parse_algorithm(member(j, "algorithm"), c);
  if (!j.contains("parameters")) throw InputError("parameters", "missing (the swept parameters: name -> list of values)");
  c.parameters = parse_parameters(j["parameters"]);
  const NameTypes param_types = [](const std::string& n) -> std::optional<ValueType> {
    const auto k = knob_of(n);
    if (!k) return std::nullopt;
    return knob_info(*k).type;
  };
  c.parameter_constraints = parse_constraints(member(j, "parameterConstraints"), "parameterConstraints", param_types, file, known_parameter_names());
  if (!j.contains("objectiveDefinitions")) throw InputError("objectiveDefinitions", "missing (at least one internal function)");
  c.objectives = parse_objectives(j["objectiveDefinitions"]);
  std::string known = known_parameter_names();
  for (const Objective& o : c.objectives) known = o.name + ", " + known;
  const std::vector<Objective>& objectives = c.objectives;
  const NameTypes objective_types = [&objectives, &param_types](const std::string& n) -> std::optional<ValueType> {
    for (const Objective& o : objectives)
      if (o.name == n) return ValueType::number;
    return param_types(n);
  };
  c.objective_constraints = parse_constraints(member(j, "objectiveConstraints"), "objectiveConstraints", objective_types, file, known);
  c.pareto = parse_ranking(member(j, "ranking"), c.objectives);
  if (c.algorithm == Algorithm::exhaustive && c.design_space_size() > kPointsMax)
    throw InputError("parameters", "the full-factorial sweep has " + std::to_string(c.design_space_size()) +
                                       " points, more than the limit " + std::to_string(kPointsMax) + " (use the genetic algorithm)");
  return c;
}

}  // namespace

uint64_t DseConfig::design_space_size() const {
  uint64_t n = 1;
  for (const SweptParameter& p : parameters) {
    n *= p.values.size();
    if (n > (uint64_t{1} << 62)) return uint64_t{1} << 62;
  }
  return n;
}

const SweptParameter* DseConfig::swept(Knob k) const {
  for (const SweptParameter& p : parameters)
    if (p.knob == k) return &p;
  return nullptr;
}

DseConfig parse_dse_config(const std::string& text, const std::string& file) {
  const Json j = json_io::parse_json_text(text, file);
  try {
    return config_from_json(j, file);
  } catch (const InputError& e) {
    if (e.where().rfind(file + ": ", 0) == 0) throw;   // a constraint's error already names the file
    throw json_io::in_file(e, file);
  }
}

DseConfig load_dse_config(const std::string& path) {
  return parse_dse_config(io_input::read_input_file(path, "DSE configuration"), path);
}

const char* function_name(Function f) {
  switch (f) {
    case Function::max: return "max";
    case Function::min: return "min";
    case Function::mean: return "mean";
  }
  return "?";
}

}  // namespace swarmcheck::dse
