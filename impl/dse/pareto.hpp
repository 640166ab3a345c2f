#pragma once
// Pareto ranking (non-dominated sorting, Deb et al. 2002 without crowding): rank 1 is the front
// of the points no other point dominates, rank 2 the front once rank 1 is removed, and so on.
// a dominates b when a is at least as good in every dimension and better in one; equal points
// share a rank. Points not ranked (infeasible, missing an objective) get rank 0.
#include <cstdint>
#include <vector>

namespace swarmcheck::dse {

struct RankInput {
  bool ranked = true;
  std::vector<double> values;   // one per dimension, oriented so that larger is better
};

std::vector<int32_t> pareto_ranks(const std::vector<RankInput>& points);

}  // namespace swarmcheck::dse
