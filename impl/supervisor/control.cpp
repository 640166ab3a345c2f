// A given supervisor's checks (spec/supervisor/control.hpp) on the compact form. The product is
// numbered in breadth-first order with events in name order, so the first violating (or
// blocking) state by id is the one with the shortlex-least word, read back along parents.
#include "impl/supervisor/operations.hpp"
#include "impl/supervisor/reach.hpp"

namespace swarmcheck::impl::supervisor {

swarmcheck::supervisor::ControlReport control_report(const Fsm& plant, const Fsm& sup) {
  WorkBudget none;
  return control_report(plant, sup, none, PeakModel{});
}

swarmcheck::supervisor::ControlReport control_report(const Fsm& plant, const Fsm& sup, WorkBudget& budget, const PeakModel& peak) {
  swarmcheck::supervisor::ControlReport r;
  const Product loop = product_with_tuples({&plant, &sup}, {"plant", "supervisor"}, budget, peak, "plant || supervisor");
  const Fsm& p = loop.fsm;
  r.closed_loop_states = p.state_count();
  const std::vector<EventId> disabled = disabled_uncontrollable(plant, loop);
  for (StateId z = 0; z < p.state_count(); ++z)
    if (disabled[z] != kNoEvent) {
      r.controllable = false;
      r.witness = event_names(p, shortlex_word(p, z));
      r.disabled_event = plant.event_names[disabled[z]];
      break;
    }
  const auto coaccessible = coaccessible_mask(p);
  for (StateId z = 0; z < p.state_count(); ++z)
    if (!coaccessible[z]) {
      r.nonblocking = false;
      r.blocking_witness = event_names(p, shortlex_word(p, z));
      break;
    }
  return r;
}

}  // namespace swarmcheck::impl::supervisor
