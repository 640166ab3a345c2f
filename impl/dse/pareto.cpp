#include "impl/dse/pareto.hpp"

#include <cstddef>

namespace swarmcheck::dse {
namespace {

bool dominates(const std::vector<double>& a, const std::vector<double>& b) {
  bool better = false;
  for (std::size_t d = 0; d < a.size(); ++d) {
    if (a[d] < b[d]) return false;
    if (a[d] > b[d]) better = true;
  }
  return better;
}

}  // namespace

std::vector<int32_t> pareto_ranks(const std::vector<RankInput>& points) {
  const std::size_t n = points.size();
  std::vector<int32_t> rank(n, 0);
  std::vector<int32_t> dominated_by(n, 0);         // how many ranked points dominate i
  std::vector<std::vector<std::size_t>> dominates_list(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!points[i].ranked) continue;
    for (std::size_t j = i + 1; j < n; ++j) {
      if (!points[j].ranked) continue;
      if (dominates(points[i].values, points[j].values)) {
        dominates_list[i].push_back(j);
        ++dominated_by[j];
      } else if (dominates(points[j].values, points[i].values)) {
        dominates_list[j].push_back(i);
        ++dominated_by[i];
      }
    }
  }
  std::vector<std::size_t> front;
  for (std::size_t i = 0; i < n; ++i)
    if (points[i].ranked && dominated_by[i] == 0) front.push_back(i);
  for (int32_t r = 1; !front.empty(); ++r) {
    std::vector<std::size_t> next;
    for (const std::size_t i : front) {
      rank[i] = r;
      for (const std::size_t j : dominates_list[i])
        if (--dominated_by[j] == 0) next.push_back(j);
    }
    front = std::move(next);
  }
  return rank;
}

}  // namespace swarmcheck::dse
