#include "spec/exploration/choice.hpp"

#include <cmath>
#include <vector>

#include "spec/exploration/rng.hpp"
#include "spec/util/demand.hpp"

namespace swarmcheck::exploration {
namespace {

int32_t first_free(std::span<const Candidate> c) {
  for (std::size_t k = 0; k < c.size(); ++k)
    if (!c[k].blocked) return static_cast<int32_t>(k);
  return -1;
}

int32_t count_free(std::span<const Candidate> c) {
  int32_t n = 0;
  for (const auto& x : c) n += x.blocked ? 0 : 1;
  return n;
}

// The k-th (0-based) free candidate.
int32_t nth_free(std::span<const Candidate> c, int32_t k) {
  for (std::size_t i = 0; i < c.size(); ++i)
    if (!c[i].blocked && k-- == 0) return static_cast<int32_t>(i);
  SWARM_DEMAND(false);
  return -1;
}

// Settle the target from the best: itself when free, else `substitute` (-1: stay).
Choice settle(std::span<const Candidate> c, int32_t best, int32_t substitute) {
  Choice ch;
  ch.best = best;
  if (!c[static_cast<std::size_t>(best)].blocked) {
    ch.target = best;
  } else {
    ch.target = substitute;
    ch.fallback = substitute >= 0;
  }
  return ch;
}

}  // namespace

Choice choose_thesis(std::span<const Candidate> c, const Params& p) {
  if (c.empty()) return Choice{};
  const double eta_term = std::pow(p.eta, p.lambda);
  double sum = 0.0;
  for (const auto& x : c) sum += std::pow(x.tau, p.phi) * eta_term;
  double best_value = std::pow(1000.0, p.phi) * eta_term / sum;
  int32_t best = -1;
  for (std::size_t k = 0; k < c.size(); ++k) {
    const double prob = std::pow(c[k].tau, p.phi) * eta_term / sum;
    if (prob <= best_value) {
      best_value = prob;
      best = static_cast<int32_t>(k);
    }
  }
  if (best < 0) best = static_cast<int32_t>(c.size()) - 1;   // every candidate tied
  return settle(c, best, first_free(c));
}

Choice choose_deterministic(std::span<const Candidate> c, const Params& p) {
  if (c.empty()) return Choice{};
  int32_t best = 0;
  double best_key = std::pow(c[0].tau, p.phi);
  for (std::size_t k = 1; k < c.size(); ++k) {
    const double key = std::pow(c[k].tau, p.phi);
    if (key <= best_key) {
      best_key = key;
      best = static_cast<int32_t>(k);
    }
  }
  return settle(c, best, first_free(c));
}

Choice choose_stochastic(std::span<const Candidate> c, const Params& p, uint64_t tie_key,
                         uint64_t fallback_key) {
  if (c.empty()) return Choice{};
  double min_key = std::pow(c[0].tau, p.phi);
  for (std::size_t k = 1; k < c.size(); ++k) min_key = std::fmin(min_key, std::pow(c[k].tau, p.phi));
  int32_t ties = 0;
  for (const auto& x : c) ties += std::pow(x.tau, p.phi) == min_key ? 1 : 0;
  SWARM_DEMAND(ties >= 1);
  int32_t pick = static_cast<int32_t>(uniform_index(tie_key, static_cast<uint32_t>(ties)));
  int32_t best = -1;
  for (std::size_t k = 0; k < c.size() && best < 0; ++k)
    if (std::pow(c[k].tau, p.phi) == min_key && pick-- == 0) best = static_cast<int32_t>(k);
  const int32_t n_free = count_free(c);
  const int32_t substitute =
      n_free == 0 ? -1
                  : nth_free(c, static_cast<int32_t>(
                                    uniform_index(fallback_key, static_cast<uint32_t>(n_free))));
  return settle(c, best, substitute);
}

}  // namespace swarmcheck::exploration
