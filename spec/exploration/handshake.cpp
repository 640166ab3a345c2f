#include "spec/exploration/handshake.hpp"


namespace swarmcheck::exploration {

template <class D>
HandshakeStepT<D> environment_handshake_rule(const HandshakeStateT<D>& s, const typename D::Bool& all_arrived) {
  using Bool = typename D::Bool;
  constexpr const char* fn = "exploration::environment_handshake_rule";
  const Bool plan = all_arrived && s.flag;
  // all arrived: the flag toggles and the output is the flag's old value; otherwise nothing.
  return {num::traced(fn, plan),
          {num::traced(fn, num::select(all_arrived, !s.flag, s.flag)),
           num::traced(fn, num::select(all_arrived, s.flag, s.output))}};
}

template <class D>
typename D::Bool handshake_stage_rule(Mode mode, HandshakeStateT<D>& s, const typename D::Bool& all_arrived) {
  if (mode != Mode::cosim) return typename D::Bool(true);
  const HandshakeStepT<D> step = environment_handshake_rule<D>(s, all_arrived);
  s = step.next;
  return num::traced("exploration::handshake_stage", step.plan);
}

template <class D>
typename D::Bool all_arrived_step_rule(const typename D::Bool& all, const typename D::Bool& output) {
  return all && output;
}

template <class D>
typename D::Bool all_arrived_rule(std::size_t n, const std::function<typename D::Bool(std::size_t)>& output_of) {
  typename D::Bool all(true);
  for (std::size_t k = 0; k < n; ++k)
    all = num::traced("exploration::all_arrived_rule", all_arrived_step_rule<D>(all, output_of(k)));
  return all;
}

template <class D>
typename D::Bool epoch_ready_step_rule(const typename D::Bool& ready, const typename D::Int& epoch,
                                       const typename D::Int& ack, const typename D::Bool& done) {
  return ready && ack == epoch && done;
}

template <class D>
typename D::Int next_epoch_rule(const typename D::Int& epoch) {
  return num::select(epoch == kEpochs - 1, typename D::Int(0), epoch + 1);
}

template <class D>
EpochStepT<D> epoch_environment_rule(const typename D::Int& epoch, std::span<const typename D::Int> acks,
                                     std::span<const typename D::Bool> done) {
  constexpr const char* fn = "exploration::epoch_environment_rule";
  typename D::Bool all(true);
  for (std::size_t k = 0; k < acks.size(); ++k) all = num::traced(fn, epoch_ready_step_rule<D>(all, epoch, acks[k], done[k]));
  const typename D::Int next = next_epoch_rule<D>(epoch);
  return {num::traced(fn, all), num::traced(fn, num::select(all, next, epoch))};
}

template <class D>
EpochControllerT<D> epoch_controller_rule(const EpochControllerT<D>& s, const typename D::Int& env_epoch,
                                          const typename D::Bool& at_waypoint) {
  constexpr const char* fn = "exploration::epoch_controller_rule";
  const typename D::Bool accept = env_epoch != s.ack;
  return {num::traced(fn, num::select(accept, env_epoch, s.ack)),
          num::traced(fn, num::select(accept, typename D::Bool(false), s.done || at_waypoint))};
}

#define SWARMCHECK_HANDSHAKE_RULES(D)                                                                          \
  template HandshakeStepT<D> environment_handshake_rule<D>(const HandshakeStateT<D>&, const D::Bool&);        \
  template D::Bool handshake_stage_rule<D>(Mode, HandshakeStateT<D>&, const D::Bool&);                         \
  template D::Bool all_arrived_step_rule<D>(const D::Bool&, const D::Bool&);                                   \
  template D::Bool epoch_ready_step_rule<D>(const D::Bool&, const D::Int&, const D::Int&, const D::Bool&);      \
  template D::Int next_epoch_rule<D>(const D::Int&);                                                           \
  template D::Bool all_arrived_rule<D>(std::size_t, const std::function<D::Bool(std::size_t)>&);                \
  template EpochStepT<D> epoch_environment_rule<D>(const D::Int&, std::span<const D::Int>,                     \
                                                   std::span<const D::Bool>);                                   \
  template EpochControllerT<D> epoch_controller_rule<D>(const EpochControllerT<D>&, const D::Int&, const D::Bool&);
SWARMCHECK_HANDSHAKE_RULES(num::Concrete)
SWARMCHECK_HANDSHAKE_RULES(num::Symbolic)
#undef SWARMCHECK_HANDSHAKE_RULES

bool handshake_stage(Mode mode, HandshakeState& s, bool all_arrived) {
  HandshakeStateT<num::Concrete> b{s.flag == 1, s.on_destination_output == 1};
  const bool plan = handshake_stage_rule<num::Concrete>(mode, b, all_arrived);
  s = HandshakeState{b.flag ? 1 : 0, b.output ? 1 : 0};
  return plan;
}

HandshakeStep environment_handshake(HandshakeState s, bool all_arrived) {
  const HandshakeStepT<num::Concrete> r =
      environment_handshake_rule<num::Concrete>({s.flag == 1, s.on_destination_output == 1}, all_arrived);
  return {r.plan, HandshakeState{r.next.flag ? 1 : 0, r.next.output ? 1 : 0}};
}

}  // namespace swarmcheck::exploration
