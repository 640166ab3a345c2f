#include "spec/exploration/choice.hpp"

#include "spec/exploration/rng.hpp"
#include "spec/util/demand.hpp"

namespace swarmcheck::exploration {
namespace {

int32_t best_thesis(std::span<const Candidate> c, const ChoiceTerms& t) {
  double sum = 0.0;
  for (const auto& x : c) sum += pheromone_key(x.tau, t.phi) * t.eta_term;
  double best_value = t.thesis_best_start / sum;
  int32_t best = -1;
  for (std::size_t k = 0; k < c.size(); ++k) {
    const double prob = pheromone_key(c[k].tau, t.phi) * t.eta_term / sum;
    if (prob <= best_value) {
      best_value = prob;
      best = static_cast<int32_t>(k);
    }
  }
  return best < 0 ? static_cast<int32_t>(c.size()) - 1 : best;   // every candidate tied
}

int32_t best_last_minimum(std::span<const Candidate> c, const ChoiceTerms& t) {
  int32_t best = 0;
  double best_key = pheromone_key(c[0].tau, t.phi);
  for (std::size_t k = 1; k < c.size(); ++k) {
    const double key = pheromone_key(c[k].tau, t.phi);
    if (key <= best_key) {
      best_key = key;
      best = static_cast<int32_t>(k);
    }
  }
  return best;
}

int32_t best_uniform_minimum(std::span<const Candidate> c, const ChoiceTerms& t, const DrawSite& site) {
  double min_key = pheromone_key(c[0].tau, t.phi);
  for (std::size_t k = 1; k < c.size(); ++k) min_key = std::fmin(min_key, pheromone_key(c[k].tau, t.phi));
  uint32_t ties = 0;
  for (const auto& x : c) ties += pheromone_key(x.tau, t.phi) == min_key ? 1U : 0U;
  SWARM_DEMAND(ties >= 1);
  uint32_t pick = uniform_index(rng_key(site.seed, site.tick, site.robot, Purpose::tie_break), ties);
  for (std::size_t k = 0; k < c.size(); ++k)
    if (pheromone_key(c[k].tau, t.phi) == min_key && pick-- == 0) return static_cast<int32_t>(k);
  SWARM_DEMAND(false);
  return -1;
}

int32_t fallback_first_free(std::span<const Candidate> c) {
  for (std::size_t k = 0; k < c.size(); ++k)
    if (!c[k].blocked) return static_cast<int32_t>(k);
  return -1;
}

int32_t fallback_uniform_free(std::span<const Candidate> c, const DrawSite& site) {
  uint32_t n_free = 0;
  for (const auto& x : c) n_free += x.blocked ? 0U : 1U;
  if (n_free == 0) return -1;
  uint32_t pick = uniform_index(rng_key(site.seed, site.tick, site.robot, Purpose::fallback), n_free);
  for (std::size_t k = 0; k < c.size(); ++k)
    if (!c[k].blocked && pick-- == 0) return static_cast<int32_t>(k);
  SWARM_DEMAND(false);
  return -1;
}

int32_t best_of(const RuleDescriptor& rules, std::span<const Candidate> c, const ChoiceTerms& t,
                const DrawSite& site) {
  switch (rules.best) {
    case BestRule::thesis_normalised: return best_thesis(c, t);
    case BestRule::last_minimum: return best_last_minimum(c, t);
    case BestRule::uniform_minimum: return best_uniform_minimum(c, t, site);
  }
  SWARM_DEMAND(false);
  return -1;
}

int32_t fallback_of(const RuleDescriptor& rules, std::span<const Candidate> c, const DrawSite& site) {
  switch (rules.fallback) {
    case FallbackRule::first_free: return fallback_first_free(c);
    case FallbackRule::uniform_free: return fallback_uniform_free(c, site);
  }
  SWARM_DEMAND(false);
  return -1;
}

}  // namespace

ChoiceTerms choice_terms(const Params& p) {
  const double eta_term = std::pow(p.eta, p.lambda);
  return ChoiceTerms{p.phi, eta_term, std::pow(1000.0, p.phi) * eta_term};
}

Choice choose(const RuleDescriptor& rules, const ChoiceTerms& terms, std::span<const Candidate> c,
              const DrawSite& site) {
  if (c.empty()) return Choice{};
  Choice ch;
  ch.best = best_of(rules, c, terms, site);
  SWARM_DEMAND(ch.best >= 0 && ch.best < static_cast<int32_t>(c.size()));
  if (!c[static_cast<std::size_t>(ch.best)].blocked) {
    ch.target = ch.best;
  } else {
    ch.target = fallback_of(rules, c, site);
    ch.fallback = ch.target >= 0;
  }
  return ch;
}

RobotDecision decide(const RuleDescriptor& rules, CellIndex current, std::span<const Candidate> c,
                     const Choice& ch) {
  RobotDecision d;
  d.deposit_centre = current;
  if (ch.best < 0) return d;   // no candidate at all (a 1 x 1 map): stay
  const CellIndex best = c[static_cast<std::size_t>(ch.best)].cell;
  if (ch.target >= 0) {
    d.moves = true;
    d.to = c[static_cast<std::size_t>(ch.target)].cell;
    d.occupies = !ch.fallback || rules.fallback_effect == FallbackEffect::occupy_and_mark;
    d.marks = d.occupies;
    d.mark = d.to;
  }
  // A blocked best and no free candidate: the robot stays and marks nothing, in every rule set
  // (the thesis's published code; its document's listing marks the best, SPEC.md section 11).
  d.deposit_centre = rules.deposit_centre == DepositCentre::best ? best : (d.moves ? d.to : current);
  return d;
}

}  // namespace swarmcheck::exploration
