// Controllability and the supremal controllable nonblocking supervisor. The fixpoint of the spec
// (supcon_good + coaccessible within the candidates) is reached incrementally: a removed state
// removes its uncontrollable predecessors through a worklist, and each coaccessibility pass only
// walks states still kept. It stops when a pass removes nothing. The product's states stay
// unnamed (pairs of plant and spec states) until a caller spells them.
#include "impl/supervisor/operations.hpp"
#include "impl/supervisor/reach.hpp"
#include "spec/util/demand.hpp"

namespace swarmcheck::impl::supervisor {

namespace {

struct Prepared {
  Product product;                         // plant || spec, unnamed
  std::vector<std::uint8_t> unc_plant;     // [events of p]: uncontrollable and in the plant
  std::vector<std::uint8_t> bad;           // [states of p]: spec disables what plant must do
};

Prepared prepare(const Fsm& plant, const Fsm& spec, WorkBudget& budget, const PeakModel& peak) {
  Prepared s;
  s.product = product_with_tuples({&plant, &spec}, {"plant", "spec"}, budget, peak);
  const Fsm& p = s.product.fsm;
  s.unc_plant.assign(p.event_count(), 0);
  for (EventId e = 0; e < plant.event_count(); ++e)
    if (!plant.controllable[e]) s.unc_plant[p.event_id(plant.event_names[e])] = 1;
  s.bad.assign(p.state_count(), 0);
  const std::vector<EventId> disabled = disabled_uncontrollable(plant, s.product);
  for (StateId z = 0; z < p.state_count(); ++z) s.bad[z] = disabled[z] != kNoEvent;
  return s;
}

bool none_bad(const Prepared& s) {
  for (const auto b : s.bad)
    if (b) return false;
  return true;
}

}  // namespace

std::vector<EventId> disabled_uncontrollable(const Fsm& plant, const Product& product) {
  const Fsm& p = product.fsm;
  std::vector<EventId> in_p(plant.event_count());
  for (EventId e = 0; e < plant.event_count(); ++e) in_p[e] = p.event_id(plant.event_names[e]);
  std::vector<EventId> out(p.state_count(), kNoEvent);
  for (StateId z = 0; z < p.state_count(); ++z) {
    const StateId x = product.names.tuple(z)[0];
    for (auto i = plant.first_edge[x]; i < plant.first_edge[x + 1] && out[z] == kNoEvent; ++i) {
      const EventId e = plant.edge_event[i];   // ascending ids: name order
      if (!plant.controllable[e] && p.successor(z, in_p[e]) == kNoState) out[z] = e;
    }
  }
  return out;
}

bool is_controllable(const Fsm& plant, const Fsm& spec) {
  WorkBudget none;
  return is_controllable(plant, spec, none, PeakModel{});
}

bool is_controllable(const Fsm& plant, const Fsm& spec, WorkBudget& budget, const PeakModel& peak) {
  return none_bad(prepare(plant, spec, budget, peak));
}

Synthesis synthesize(const Fsm& plant, const Fsm& spec, std::uint64_t max_bytes) {
  WorkBudget budget(max_bytes);
  return synthesize(plant, spec, budget, PeakModel{0, 208.0, 16.0});
}

Synthesis synthesize(const Fsm& plant, const Fsm& spec, WorkBudget& budget, const PeakModel& peak) {
  Prepared s = prepare(plant, spec, budget, peak);
  const Fsm& p = s.product.fsm;
  const StateId n = p.state_count();
  std::vector<std::uint8_t> kept(n, 1);
  {
    const ReverseEdges unc = reverse_edges(p, &s.unc_plant);
    const ReverseEdges all = reverse_edges(p);
    std::vector<StateId> work;
    auto remove = [&](StateId z) {
      kept[z] = 0;
      work.push_back(z);
    };
    for (StateId z = 0; z < n; ++z)
      if (s.bad[z]) remove(z);
    // A pass is linear in the product, and there may be as many passes as states: the time limit
    // is checked between them.
    int passes = 0;
    for (;; ++passes) {
      budget.check("plant || spec", peak.at(static_cast<double>(n), static_cast<double>(p.edge_count())), [&] {
        return "synthesis stopped after " + std::to_string(passes) + " passes of its fixpoint over plant || spec (" +
               std::to_string(n) + " states)";
      });
      while (!work.empty()) {  // removal closes over uncontrollable predecessors
        const StateId z = work.back();
        work.pop_back();
        for (auto i = unc.first[z]; i < unc.first[z + 1]; ++i)
          if (kept[unc.source[i]]) remove(unc.source[i]);
      }
      // Coaccessible through kept states only; a kept state that is not must go too.
      const auto reach = coreachable(all, p.marked, &kept);
      for (StateId z = 0; z < n; ++z)
        if (kept[z] && !reach[z]) remove(z);
      if (work.empty()) break;
    }
  }  // the reverse edges are freed before the result is built
  Synthesis out;
  out.spec_controllable = none_bad(s);
  std::vector<StateId> from_p, from_kept;
  const Fsm candidates = restrict_states(p, kept, &from_p);
  out.supervisor = restrict_states(candidates, accessible_mask(candidates), &from_kept);
  out.names.parts = {&plant, &spec};
  out.names.tuples.reserve(2 * from_kept.size());
  for (const StateId k : from_kept) {
    const StateId* t = s.product.names.tuple(from_p[k]);
    out.names.tuples.insert(out.names.tuples.end(), t, t + 2);
  }
  return out;
}

Fsm supcon(const Fsm& plant, const Fsm& spec, std::uint64_t max_bytes) {
  Synthesis s = synthesize(plant, spec, max_bytes);
  store_names(s.supervisor, s.names);
  return std::move(s.supervisor);
}

}  // namespace swarmcheck::impl::supervisor
