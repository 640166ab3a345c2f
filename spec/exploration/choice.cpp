#include "spec/exploration/choice.hpp"

#include "spec/exploration/rng.hpp"
#include "spec/util/demand.hpp"

namespace swarmcheck::exploration {
namespace {

// A draw in [0, n): the seeded generator (concrete) or a free choice (symbolic).
int32_t draw_index(const DrawSite& site, Purpose purpose, int32_t n) {
  return static_cast<int32_t>(uniform_index(rng_key(site.seed, site.tick, site.robot, purpose), static_cast<uint32_t>(n)));
}
sym::Int draw_index(const SymbolicDrawSite& site, Purpose purpose, const sym::Int& n) {
  return sym::Int::draw(n, site.name + (purpose == Purpose::tie_break ? ".tie_break" : ".fallback"));
}

// The candidate at a (possibly symbolic) index is blocked.
bool blocked_at(std::span<const Candidate> c, int32_t k) { return c[static_cast<std::size_t>(k)].blocked; }
sym::Bool blocked_at(std::span<const SymbolicCandidate> c, const sym::Int& k) {
  sym::Bool b(false);
  for (std::size_t i = 0; i < c.size(); ++i) b = b || (k == static_cast<int32_t>(i) && c[i].blocked);
  return b;
}

// The cell of the candidate at a (possibly symbolic) index; the symbolic one is (0, 0) at an
// index that names none.
CellIndex cell_at(std::span<const Candidate> c, int32_t k) { return c[static_cast<std::size_t>(k)].cell; }
CellOf<num::Symbolic> cell_at(std::span<const SymbolicCandidate> c, const sym::Int& k) {
  CellOf<num::Symbolic> out{sym::Int(0), sym::Int(0)};
  for (std::size_t i = 0; i < c.size(); ++i) {
    const sym::Bool here = k == static_cast<int32_t>(i);
    out = {sym::select(here, c[i].cell[0], out[0]), sym::select(here, c[i].cell[1], out[1])};
  }
  return out;
}

template <class D>
CellOf<D> select_cell(const typename D::Bool& c, const CellOf<D>& a, const CellOf<D>& b) {
  return {num::select(c, a[0], b[0]), num::select(c, a[1], b[1])};
}

// Whether a candidate is in the list (always, for a concrete one).
constexpr bool present(const Candidate&) { return true; }
const sym::Bool& present(const SymbolicCandidate& c) { return c.present; }

template <class D>
typename D::Int index(std::size_t k) {
  return typename D::Int(static_cast<int32_t>(k));
}

template <class D>
typename D::Int best_thesis(std::span<const CandidateOf<D>> c, const ChoiceTermsT<D>& t) {
  using Real = typename D::Real;
  Real sum(0.0);
  typename D::Int last(-1);
  for (std::size_t k = 0; k < c.size(); ++k) {
    sum = num::select(present(c[k]), sum + pheromone_key_rule<D>(c[k].tau, t.phi) * t.eta_term, sum);
    last = num::select(present(c[k]), index<D>(k), last);
  }
  Real best_value = t.thesis_best_start / sum;
  typename D::Int best(-1);
  for (std::size_t k = 0; k < c.size(); ++k) {
    const Real prob = pheromone_key_rule<D>(c[k].tau, t.phi) * t.eta_term / sum;
    const typename D::Bool take = present(c[k]) && prob <= best_value;
    best_value = num::select(take, prob, best_value);
    best = num::select(take, index<D>(k), best);
  }
  return num::select(best < 0, last, best);   // every candidate tied: the last one
}

template <class D>
typename D::Int best_last_minimum(std::span<const CandidateOf<D>> c, const ChoiceTermsT<D>& t) {
  typename D::Int best(-1);
  typename D::Real best_key(0.0);
  for (std::size_t k = 0; k < c.size(); ++k) {
    const typename D::Real key = pheromone_key_rule<D>(c[k].tau, t.phi);
    const typename D::Bool take = present(c[k]) && (best < 0 || key <= best_key);
    best_key = num::select(take, key, best_key);
    best = num::select(take, index<D>(k), best);
  }
  return best;
}

template <class D>
typename D::Int best_uniform_minimum(std::span<const CandidateOf<D>> c, const ChoiceTermsT<D>& t,
                                     const DrawSiteOf<D>& site) {
  using Int = typename D::Int;
  typename D::Real min_key(0.0);
  typename D::Bool any(false);
  for (std::size_t k = 0; k < c.size(); ++k) {
    const typename D::Real key = pheromone_key_rule<D>(c[k].tau, t.phi);
    min_key = num::select(present(c[k]), num::select(any, num::fmin(min_key, key), key), min_key);
    any = any || present(c[k]);
  }
  Int ties(0);
  for (const auto& x : c)
    ties = ties + num::select(present(x) && pheromone_key_rule<D>(x.tau, t.phi) == min_key, Int(1), Int(0));
  if constexpr (num::is_concrete<D>) SWARM_DEMAND(ties >= 1);
  const Int pick = draw_index(site, Purpose::tie_break, ties);
  Int seen(0), chosen(-1);
  for (std::size_t k = 0; k < c.size(); ++k) {
    const typename D::Bool is_min = present(c[k]) && pheromone_key_rule<D>(c[k].tau, t.phi) == min_key;
    chosen = num::select(is_min && seen == pick, index<D>(k), chosen);
    seen = seen + num::select(is_min, Int(1), Int(0));
  }
  return chosen;
}

template <class D>
typename D::Int fallback_first_free(std::span<const CandidateOf<D>> c) {
  typename D::Int first(-1);   // built backwards: the first free one wins
  for (std::size_t k = c.size(); k-- > 0;) first = num::select(present(c[k]) && !c[k].blocked, index<D>(k), first);
  return first;
}

template <class D>
typename D::Int fallback_uniform_free(std::span<const CandidateOf<D>> c, const DrawSiteOf<D>& site) {
  using Int = typename D::Int;
  Int n_free(0);
  for (const auto& x : c) n_free = n_free + num::select(present(x) && !x.blocked, Int(1), Int(0));
  return num::branch(n_free == 0, [] { return Int(-1); }, [&] {
    const Int pick = draw_index(site, Purpose::fallback, n_free);
    Int seen(0), chosen(-1);
    for (std::size_t k = 0; k < c.size(); ++k) {
      const typename D::Bool free = present(c[k]) && !c[k].blocked;
      chosen = num::select(free && seen == pick, index<D>(k), chosen);
      seen = seen + num::select(free, Int(1), Int(0));
    }
    return chosen;
  });
}

template <class D>
typename D::Int best_of(const RuleDescriptor& rules, std::span<const CandidateOf<D>> c, const ChoiceTermsT<D>& t,
                        const DrawSiteOf<D>& site) {
  switch (rules.best) {
    case BestRule::thesis_normalised: return best_thesis<D>(c, t);
    case BestRule::last_minimum: return best_last_minimum<D>(c, t);
    case BestRule::uniform_minimum: return best_uniform_minimum<D>(c, t, site);
  }
  SWARM_DEMAND(false);
  return -1;
}

template <class D>
typename D::Int fallback_of(const RuleDescriptor& rules, std::span<const CandidateOf<D>> c, const DrawSiteOf<D>& site) {
  switch (rules.fallback) {
    case FallbackRule::first_free: return fallback_first_free<D>(c);
    case FallbackRule::uniform_free: return fallback_uniform_free<D>(c, site);
  }
  SWARM_DEMAND(false);
  return -1;
}

}  // namespace

template <class D>
ChoiceT<D> choose_rule(const RuleDescriptor& rules, const ChoiceTermsT<D>& terms,
                       std::span<const CandidateOf<D>> c, const DrawSiteOf<D>& site) {
  if (c.empty()) return ChoiceT<D>{};
  ChoiceT<D> ch;
  ch.best = best_of<D>(rules, c, terms, site);
  if constexpr (num::is_concrete<D>) SWARM_DEMAND(ch.best >= 0 && ch.best < static_cast<int32_t>(c.size()));
  const typename D::Bool blocked = blocked_at(c, ch.best);
  ch.target = num::branch(blocked, [&] { return fallback_of<D>(rules, c, site); }, [&] { return ch.best; });
  ch.fallback = blocked && ch.target >= 0;
  return ch;
}

template ChoiceT<num::Concrete> choose_rule<num::Concrete>(const RuleDescriptor&, const ChoiceTermsT<num::Concrete>&,
                                                            std::span<const Candidate>, const DrawSite&);
template ChoiceT<num::Symbolic> choose_rule<num::Symbolic>(const RuleDescriptor&, const ChoiceTermsT<num::Symbolic>&,
                                                            std::span<const SymbolicCandidate>,
                                                            const SymbolicDrawSite&);

ChoiceTerms choice_terms(const Params& p) {
  const double eta_term = std::pow(p.eta, p.lambda);
  return ChoiceTerms{p.phi, eta_term, std::pow(1000.0, p.phi) * eta_term};
}

// Flattened: choose_rule, inlined here, writes the fields straight into `out` (called, it returns
// the Choice through the stack: the store-forwarding stall described at choose_into in choice.hpp).
#if defined(__GNUC__)
[[gnu::flatten]]
#endif
void choose_into(const RuleDescriptor& rules, const ChoiceTerms& terms, std::span<const Candidate> c,
                 const DrawSite& site, Choice& out) {
  out = choose_rule<num::Concrete>(rules, terms, c, site);
}

template <class D>
RobotDecisionT<D> decide_rule(const RuleDescriptor& rules, const CellOf<D>& current,
                              std::span<const CandidateOf<D>> c, const ChoiceT<D>& ch) {
  using Bool = typename D::Bool;
  RobotDecisionT<D> stay;
  stay.deposit_centre = current;
  const auto chosen = [&] {
    const CellOf<D> best = cell_at(c, ch.best);
    const auto moved = [&] {
      RobotDecisionT<D> m = stay;
      m.moves = Bool(true);
      m.to = cell_at(c, ch.target);
      m.occupies = !ch.fallback || Bool(rules.fallback_effect == FallbackEffect::occupy_and_mark);
      m.marks = m.occupies;
      m.mark = m.to;
      return m;
    };
    RobotDecisionT<D> d = num::branch(ch.target >= 0, moved, [&] { return stay; });
    // A blocked best and no free candidate: the robot stays and marks nothing, in every rule set
    // (the thesis's published code; its document's listing marks the best, SPEC.md section 11).
    d.deposit_centre = rules.deposit_centre == DepositCentre::best ? best : select_cell<D>(d.moves, d.to, current);
    return d;
  };
  // No candidate at all (a 1 x 1 map): stay.
  RobotDecisionT<D> d = num::branch(ch.best < 0, [&] { return stay; }, chosen);
  constexpr const char* fn = "exploration::decide";
  auto cell = [&](const CellOf<D>& x) { return CellOf<D>{num::traced(fn, x[0]), num::traced(fn, x[1])}; };
  return {num::traced(fn, d.moves), cell(d.to),          num::traced(fn, d.occupies),
          num::traced(fn, d.marks), cell(d.mark), cell(d.deposit_centre)};
}

template RobotDecisionT<num::Concrete> decide_rule<num::Concrete>(const RuleDescriptor&, const CellIndex&,
                                                                  std::span<const Candidate>, const Choice&);
template RobotDecisionT<num::Symbolic> decide_rule<num::Symbolic>(const RuleDescriptor&, const CellOf<num::Symbolic>&,
                                                                  std::span<const SymbolicCandidate>,
                                                                  const ChoiceT<num::Symbolic>&);

RobotDecision decide(const RuleDescriptor& rules, CellIndex current, std::span<const Candidate> c, const Choice& ch) {
  return decide_rule<num::Concrete>(rules, current, c, ch);
}

RobotDecisionT<num::Symbolic> decide(const RuleDescriptor& rules, const CellOf<num::Symbolic>& current,
                                     std::span<const SymbolicCandidate> c, const ChoiceT<num::Symbolic>& ch) {
  return decide_rule<num::Symbolic>(rules, current, c, ch);
}

ChoiceT<num::Symbolic> choose(const RuleDescriptor& rules, const ChoiceTermsT<num::Symbolic>& terms,
                              std::span<const SymbolicCandidate> c, const SymbolicDrawSite& site) {
  const ChoiceT<num::Symbolic> ch = choose_rule<num::Symbolic>(rules, terms, c, site);
  constexpr const char* fn = "exploration::choose_rule";
  return {num::traced(fn, ch.best), num::traced(fn, ch.target), num::traced(fn, ch.fallback)};
}

std::optional<RobotDecision> walled_in_decision(const RuleDescriptor& rules, CellIndex current) {
  if (rules.deposit_centre != DepositCentre::robot_cell || !rules.keeps_occupancy_invariants) return std::nullopt;
  RobotDecision d;
  d.deposit_centre = current;
  return d;
}

}  // namespace swarmcheck::exploration
