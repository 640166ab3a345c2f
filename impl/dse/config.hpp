#pragma once
// A DSE configuration in INTO-CPS's format (the `.dse.json` its DSE scripts read):
//
//   {"algorithm": {"type": "exhaustive"} | {"type": "genetic", ...},
//    "parameters": {"{Environment}.EnvironmentInstance.ertu_perc": [0.07, 0.06], ...},
//    "parameterConstraints": ["a1 <= a2", ...],
//    "objectiveDefinitions": {"externalScripts": {},
//                             "internalFunctions": {"NAME": {"columnID": "...", "objectiveType": "max|min|mean"}}},
//    "objectiveConstraints": ["NAME > 90", ...],
//    "ranking": {"pareto": {"NAME": "+" | "-"}},
//    "scenarios": []}
//
// Parameters are swept full factorial, the first one slowest. Every problem is an InputError
// naming the JSON path (and, in a constraint, the column) and what was expected.
#include <cstdint>
#include <string>
#include <vector>

#include "impl/dse/expression.hpp"
#include "impl/dse/names.hpp"
#include "spec/util/hana_json.hpp"

namespace swarmcheck::dse {

struct ParameterValue {
  double number = 0;   // numeric knobs
  std::string text;    // rule, mode
  json_io::Json json;  // as written (for the outputs)
};

struct SweptParameter {
  std::string name;   // as written in the configuration
  Knob knob = Knob::ertu;
  std::vector<ParameterValue> values;
};

enum class Function : uint8_t { max, min, mean };

struct Objective {
  std::string name;      // the key in internalFunctions
  std::string column_id; // as written
  Column column;
  Function function = Function::max;
};

struct Constraint {
  std::string path;   // "parameterConstraints[0]"
  Expression expression;
};

struct ParetoDimension {
  std::size_t objective = 0;   // index into DseConfig::objectives
  bool maximise = true;        // "+" maximise, "-" minimise
};

enum class Algorithm : uint8_t { exhaustive, genetic };
enum class InitialDistribution : uint8_t { random, uniform };
enum class ParentSelection : uint8_t { random, objective_space };

// INTO-CPS's genetic search options, plus the limits and the seed swarmcheck adds.
struct GeneticOptions {
  int32_t initial_population = 10;                  // initialPopulation, in [2, 10000]
  InitialDistribution distribution = InitialDistribution::random;   // initialPopulationDistribution
  double mutation_probability = 0.1;                // mutationProbability, given in percent [0, 100]
  ParentSelection selection = ParentSelection::objective_space;     // parentSelectionStrategy
  int32_t max_generations_without_improvement = 5;  // in [1, 1000]
  int32_t max_generations = 100;                    // maxGenerations, in [1, 10000]
  uint64_t seed = 1;                                // seed
};

struct DseConfig {
  std::string file;
  std::vector<SweptParameter> parameters;
  std::vector<Constraint> parameter_constraints;
  std::vector<Objective> objectives;
  std::vector<Constraint> objective_constraints;
  std::vector<ParetoDimension> pareto;
  Algorithm algorithm = Algorithm::exhaustive;
  GeneticOptions genetic;

  // Full-factorial size (saturates at 2^62).
  uint64_t design_space_size() const;
  // The swept parameter that sets this knob, or nullptr.
  const SweptParameter* swept(Knob k) const;
};

inline constexpr int32_t kReplicatesMax = 1000;
inline constexpr std::size_t kPointsMax = std::size_t{1} << 24;   // exhaustive sweeps at most

DseConfig parse_dse_config(const std::string& text, const std::string& file);
DseConfig load_dse_config(const std::string& path);

const char* function_name(Function f);

}  // namespace swarmcheck::dse
