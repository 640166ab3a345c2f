#pragma once
// Design points: a genome (one value index per swept parameter) applied to the base scenario.
//
// A point runs `replicates` times (1 unless swept). Replicate 0 uses the point's seed (the base
// scenario's, or the swept `seed`), so a one-replicate point is exactly `swarmcheck run` of its
// scenario; replicate r >= 1 uses replicate_seed(seed, r). Each run's seeded placement (nRobots,
// nObstacles, obstacleDensity) is drawn from that run's seed: obstacles first (never on a base
// robot's cell when the robots are kept), then robots on distinct free cells, at cell centres.
#include <cstdint>
#include <string>
#include <vector>

#include "impl/dse/config.hpp"
#include "spec/exploration/types.hpp"

namespace swarmcheck::dse {

using Genome = std::vector<int32_t>;

// The seed of replicate r >= 1 of a point whose seed is `seed` (SplitMix64-derived).
uint64_t replicate_seed(uint64_t seed, int32_t replicate);

class DesignSpace {
 public:
  DesignSpace(const DseConfig& config, exploration::Scenario base);

  const DseConfig& config() const { return config_; }
  const exploration::Scenario& base() const { return base_; }
  uint64_t size() const { return config_.design_space_size(); }

  // The index-th point of the full factorial (the first parameter varies slowest), and back.
  Genome genome_of(uint64_t index) const;
  uint64_t index_of(const Genome& g) const;

  int32_t replicates(const Genome& g) const;
  // Replicate r's scenario, validated: bad combinations are InputErrors naming the point.
  exploration::Scenario scenario(const Genome& g, int32_t replicate) const;
  // The value a constraint sees for a knob: the swept value, else the base scenario's.
  Value knob_value(const Genome& g, Knob k) const;
  // The first parameterConstraints entry the point violates, or -1.
  int32_t violated_parameter_constraint(const Genome& g) const;
  // A hash of everything the point's runs depend on (every replicate's full scenario and the
  // tool version), 16 hex digits: the journal's key.
  std::string point_key(const Genome& g) const;
  // "ertu_perc=0.07, nRobots=100" (plain names); varying_only leaves out the parameters swept
  // over one value (unless every parameter is).
  std::string describe(const Genome& g, bool varying_only = false) const;

 private:
  const ParameterValue* value(const Genome& g, Knob k) const;

  const DseConfig& config_;
  exploration::Scenario base_;
};

}  // namespace swarmcheck::dse
