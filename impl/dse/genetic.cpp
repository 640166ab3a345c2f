#include "impl/dse/genetic.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "impl/dse/sweep.hpp"
#include "spec/exploration/rng.hpp"

namespace swarmcheck::dse {
namespace {

__extension__ using U128 = unsigned __int128;   // for exact 64x64 -> 128-bit products

using exploration::splitmix64;

// A counter-based stream: draw c is a pure function of (seed, c).
class Stream {
 public:
  explicit Stream(uint64_t seed) : key_(splitmix64(seed ^ 0x67656e6574696373ULL)) {}   // "genetics"
  uint64_t next() { return splitmix64(key_ ^ splitmix64(counter_++)); }
  int64_t below(int64_t n) {
    return static_cast<int64_t>((static_cast<U128>(next()) * static_cast<uint64_t>(n)) >> 64);
  }
  double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

 private:
  uint64_t key_;
  uint64_t counter_ = 0;
};

class Search {
 public:
  Search(const DesignSpace& space, const BatchEvaluator& evaluate)
      : space_(space), options_(space.config().genetic), evaluate_(evaluate), rng_(options_.seed) {}

  GeneticOutcome run();

 private:
  bool feasible(const Genome& g) {
    const auto known = feasible_.find(g);
    if (known != feasible_.end()) return known->second;
    const bool ok = space_.violated_parameter_constraint(g) < 0 && !point_problem(space_, g);
    feasible_.emplace(g, ok);
    return ok;
  }
  Genome random_genome() {
    Genome g;
    for (const SweptParameter& p : space_.config().parameters)
      g.push_back(static_cast<int32_t>(rng_.below(static_cast<int64_t>(p.values.size()))));
    return g;
  }
  std::vector<Genome> initial_population();
  std::vector<Genome> breed(const std::vector<Genome>& population);
  const Genome& pick_parent(const std::vector<Genome>& population);
  bool evaluate(const std::vector<Genome>& batch, int32_t generation);
  int32_t rank_of(const Genome& g) const;   // 0 (unranked) sorts last
  std::set<std::size_t> current_front();

  const DesignSpace& space_;
  const GeneticOptions& options_;
  const BatchEvaluator& evaluate_;
  Stream rng_;
  std::map<Genome, bool> feasible_;
  std::map<Genome, std::size_t> evaluated_;   // genome -> index in out_.points
  std::vector<int32_t> ranks_;                // by index in out_.points
  GeneticOutcome out_;
};

std::vector<Genome> Search::initial_population() {
  const std::size_t want = static_cast<std::size_t>(options_.initial_population);
  const uint64_t size = space_.size();
  std::vector<Genome> pop;
  std::set<Genome> seen;
  const std::size_t attempts_max = 100 * want;
  uint64_t offset = 0;   // uniform: steps past a taken or infeasible spot
  for (std::size_t attempt = 0; pop.size() < want && attempt < attempts_max; ++attempt) {
    Genome g;
    if (options_.distribution == InitialDistribution::random) {
      g = random_genome();
    } else {
      // Evenly spread over the factorial order: member k at the middle of its 1/want slice.
      const uint64_t spot = static_cast<uint64_t>((static_cast<U128>(2 * pop.size() + 1) * size) / (2 * want));
      g = space_.genome_of((spot + offset++) % size);
    }
    if (!seen.count(g) && feasible(g)) {
      seen.insert(g);
      pop.push_back(g);
      offset = 0;
    }
  }
  return pop;
}

const Genome& Search::pick_parent(const std::vector<Genome>& population) {
  const auto draw = [&]() -> const Genome& {
    return population[static_cast<std::size_t>(rng_.below(static_cast<int64_t>(population.size())))];
  };
  if (options_.selection == ParentSelection::random) return draw();
  const Genome& a = draw();
  const Genome& b = draw();
  const auto key = [&](const Genome& g) { return std::make_pair(rank_of(g), evaluated_.at(g)); };
  return key(a) <= key(b) ? a : b;
}

std::vector<Genome> Search::breed(const std::vector<Genome>& population) {
  const std::size_t want = population.size();
  std::vector<Genome> children;
  std::set<Genome> seen;
  const auto& params = space_.config().parameters;
  for (std::size_t attempt = 0; children.size() < want && attempt < 50 * want; ++attempt) {
    const Genome& a = pick_parent(population);
    const Genome& b = pick_parent(population);
    Genome child(a.size());
    for (std::size_t k = 0; k < child.size(); ++k) {
      child[k] = (rng_.next() >> 63) ? a[k] : b[k];
      if (rng_.unit() < options_.mutation_probability)
        child[k] = static_cast<int32_t>(rng_.below(static_cast<int64_t>(params[k].values.size())));
    }
    if (!seen.count(child) && feasible(child)) {
      seen.insert(child);
      children.push_back(std::move(child));
    }
  }
  return children;
}

bool Search::evaluate(const std::vector<Genome>& batch, int32_t generation) {
  std::vector<Genome> fresh;
  for (const Genome& g : batch)
    if (!evaluated_.count(g) && std::find(fresh.begin(), fresh.end(), g) == fresh.end()) fresh.push_back(g);
  if (!fresh.empty()) {
    const auto outcomes = evaluate_(fresh, generation);
    if (!outcomes) return false;
    for (std::size_t k = 0; k < fresh.size(); ++k) {
      evaluated_.emplace(fresh[k], out_.points.size());
      PointOutcome o = (*outcomes)[k];
      o.generation = generation;
      out_.points.push_back(std::move(o));
    }
  }
  const DseResults ranked = rank_outcomes(space_, out_.points);
  ranks_.clear();
  for (const PointResult& p : ranked.points) ranks_.push_back(p.rank);
  return true;
}

int32_t Search::rank_of(const Genome& g) const {
  const int32_t r = ranks_[evaluated_.at(g)];
  return r == 0 ? INT32_MAX : r;
}

std::set<std::size_t> Search::current_front() {
  std::set<std::size_t> f;
  for (std::size_t i = 0; i < ranks_.size(); ++i)
    if (ranks_[i] == 1) f.insert(i);
  return f;
}

GeneticOutcome Search::run() {
  std::vector<Genome> population = initial_population();
  if (population.empty()) return out_;
  if (!evaluate(population, 0)) return GeneticOutcome{out_.points, 0, true};
  out_.generations = 1;
  std::set<std::size_t> front = current_front();
  int32_t stagnant = 0;
  for (int32_t g = 1; g < options_.max_generations && stagnant < options_.max_generations_without_improvement; ++g) {
    const std::vector<Genome> children = breed(population);
    if (children.empty()) break;
    if (!evaluate(children, g)) return GeneticOutcome{out_.points, out_.generations, true};
    out_.generations = g + 1;
    std::vector<Genome> pool = population;
    for (const Genome& c : children)
      if (std::find(pool.begin(), pool.end(), c) == pool.end()) pool.push_back(c);
    std::stable_sort(pool.begin(), pool.end(), [&](const Genome& a, const Genome& b) {
      return std::make_pair(rank_of(a), evaluated_.at(a)) < std::make_pair(rank_of(b), evaluated_.at(b));
    });
    pool.resize(std::min(pool.size(), static_cast<std::size_t>(options_.initial_population)));
    population = std::move(pool);
    const std::set<std::size_t> now = current_front();
    if (now == front) {
      ++stagnant;
    } else {
      stagnant = 0;
      front = now;
    }
  }
  return out_;
}

}  // namespace

GeneticOutcome run_genetic(const DesignSpace& space, const BatchEvaluator& evaluate) {
  return Search(space, evaluate).run();
}

}  // namespace swarmcheck::dse
