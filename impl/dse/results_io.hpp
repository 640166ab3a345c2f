#pragma once
// The results files: results.csv (one row per design point) and results.json (the same, with
// every replicate's value), and the texts the report and the summary share. Their bytes are a
// function of the configuration, the base scenario's label and the results alone.
//
// results.csv columns: point (from 1), generation (genetic search only), each swept parameter
// (named as in the configuration), each objective's mean and, when a point has replicates,
// <objective>_ci95 (the 95 % interval's half-width), runs (the replicates run), status, rank (Pareto rank,
// empty when not ranked), pareto_front (true/false).
#include <string>

#include "impl/dse/design_space.hpp"
#include "impl/dse/results.hpp"
#include "spec/util/hana_json.hpp"

namespace swarmcheck::dse {

struct ResultsContext {
  std::string config_label;     // the configuration file as given
  std::string scenario_label;   // the base scenario file as given, or "default scenario"
};

std::string results_csv(const DesignSpace& space, const DseResults& r);
json_io::Json results_json(const DesignSpace& space, const DseResults& r, const ResultsContext& ctx);

// "+" / "-" when the objective is a Pareto dimension, else "".
std::string objective_direction(const DseConfig& c, std::size_t objective);
bool any_replicated(const DseResults& r);
std::string parameter_value_text(const DesignSpace& space, const Genome& g, std::size_t parameter);

}  // namespace swarmcheck::dse
