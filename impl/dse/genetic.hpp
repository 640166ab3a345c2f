#pragma once
// The genetic search over the swept value lists (INTO-CPS's genetic DSE, seeded):
//
//   generation 0: `initialPopulation` distinct feasible points, drawn uniformly at random or
//                 spread evenly over the full factorial (initialPopulationDistribution);
//   generation g: as many children, each from two parents (parentSelectionStrategy: uniformly
//                 at random, or `algorithmObjectiveSpace`: binary tournaments on Pareto rank),
//                 uniform crossover, then each gene mutated to a random value with
//                 mutationProbability; the next population is the best of parents and children
//                 (Pareto rank, then order of first evaluation);
//   stop:         after maxGenerationsWithoutImprovement generations that add no point to the
//                 Pareto front, after maxGenerations, or when nothing new can be drawn.
//
// Feasible: satisfies the parameter constraints and makes valid scenarios. Every draw comes from
// one counter-based stream keyed by the seed, and the search sees only completed generations,
// so the points it visits never depend on how a generation was evaluated.
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "impl/dse/design_space.hpp"
#include "impl/dse/results.hpp"

namespace swarmcheck::dse {

// Outcomes of a batch, in batch order; nullopt when the sweep was interrupted.
using BatchEvaluator = std::function<std::optional<std::vector<PointOutcome>>(const std::vector<Genome>&, int32_t generation)>;

struct GeneticOutcome {
  std::vector<PointOutcome> points;   // in order of first evaluation
  int32_t generations = 0;
  bool interrupted = false;
};

GeneticOutcome run_genetic(const DesignSpace& space, const BatchEvaluator& evaluate);

}  // namespace swarmcheck::dse
