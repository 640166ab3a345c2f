// Parallel planning by independent groups.
//
// A robot's decision reads and writes only cells of its window (Chebyshev radius s around its
// cell): it reads pheromone and occupancy there, and its move and visit marks stay there. Two
// robots more than 2s apart therefore touch disjoint cells, whatever either does. Robots are
// joined (union-find) when they are within 2s; each group runs in robot-index order, as the
// sequential loop would, and groups run in parallel. The result is exactly the sequential one.
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <numeric>

#include "impl/exploration/environment.hpp"

namespace swarmcheck::impl::exploration {
namespace {

struct UnionFind {
  std::vector<int32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int32_t find(int32_t x) {
    while (parent[static_cast<std::size_t>(x)] != x) {
      parent[static_cast<std::size_t>(x)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
      x = parent[static_cast<std::size_t>(x)];
    }
    return x;
  }
  void unite(int32_t a, int32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
  }
};

// Groups of robots (each sorted by index) such that robots of different groups are > reach apart.
std::vector<std::vector<int32_t>> independent_groups(const std::vector<swarmcheck::exploration::CellIndex>& cells,
                                                     int32_t reach) {
  const auto n = cells.size();
  const int64_t bucket = std::max<int64_t>(1, reach);
  auto key_of = [&](int64_t bi, int64_t bj) { return (bi << 32) ^ (bj & 0xffffffff); };
  std::vector<std::pair<int64_t, int32_t>> keyed(n);
  for (std::size_t r = 0; r < n; ++r)
    keyed[r] = {key_of(cells[r][0] / bucket, cells[r][1] / bucket), static_cast<int32_t>(r)};
  std::sort(keyed.begin(), keyed.end());
  UnionFind uf(n);
  for (std::size_t r = 0; r < n; ++r) {
    const int64_t bi = cells[r][0] / bucket, bj = cells[r][1] / bucket;
    for (int64_t di = -1; di <= 1; ++di)
      for (int64_t dj = -1; dj <= 1; ++dj) {
        const int64_t key = key_of(bi + di, bj + dj);
        auto it = std::lower_bound(keyed.begin(), keyed.end(), std::pair<int64_t, int32_t>{key, -1});
        for (; it != keyed.end() && it->first == key; ++it) {
          const auto& other = cells[static_cast<std::size_t>(it->second)];
          if (std::abs(other[0] - cells[r][0]) <= reach && std::abs(other[1] - cells[r][1]) <= reach)
            uf.unite(static_cast<int32_t>(r), it->second);
        }
      }
  }
  std::vector<int32_t> group_of(n, -1);
  std::vector<std::vector<int32_t>> groups;
  for (std::size_t r = 0; r < n; ++r) {
    const auto root = static_cast<std::size_t>(uf.find(static_cast<int32_t>(r)));
    if (group_of[root] < 0) {
      group_of[root] = static_cast<int32_t>(groups.size());
      groups.emplace_back();
    }
    groups[static_cast<std::size_t>(group_of[root])].push_back(static_cast<int32_t>(r));
  }
  return groups;
}

}  // namespace

int64_t Environment::plan_grouped(swarmcheck::exploration::EnvironmentState& env, LazyGrid& grid) const {
  const int32_t reach = cfg_.scenario.params.s_range > cfg_.scenario.map_size ? cfg_.scenario.map_size
                                                                              : 2 * cfg_.scenario.params.s_range;
  std::vector<CellIndex> cells(env.robots.size());
  for (std::size_t r = 0; r < cells.size(); ++r) cells[r] = env.robots[r].cell;
  const auto groups = independent_groups(cells, reach);
  std::vector<int64_t> newly(groups.size(), 0);
  tbb::enumerable_thread_specific<std::vector<Candidate>> scratch;
  tbb::parallel_for(std::size_t{0}, groups.size(), [&](std::size_t g) {
    std::vector<Candidate>& w = scratch.local();
    for (int32_t r : groups[g]) newly[g] += swarmcheck::exploration::plan_robot(cfg_, env, grid, r, w);
  });
  int64_t total = 0;
  for (int64_t v : newly) total += v;
  return total;
}

}  // namespace swarmcheck::impl::exploration
