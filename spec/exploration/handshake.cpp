#include "spec/exploration/handshake.hpp"


namespace swarmcheck::exploration {

template <class D>
HandshakeStepT<D> environment_handshake_rule(const HandshakeStateT<D>& s, const typename D::Bool& all_arrived) {
  using Bool = typename D::Bool;
  const Bool plan = all_arrived && s.flag;
  // all arrived: the flag toggles and the output is the flag's old value; otherwise nothing.
  return {plan, {num::select(all_arrived, !s.flag, s.flag), num::select(all_arrived, s.flag, s.output)}};
}

template <class D>
typename D::Bool all_arrived_rule(std::size_t n, const std::function<typename D::Bool(std::size_t)>& output_of) {
  typename D::Bool all(true);
  for (std::size_t k = 0; k < n; ++k) all = all && output_of(k);
  return all;
}

template <class D>
EpochStepT<D> epoch_environment_rule(const typename D::Int& epoch, std::span<const typename D::Int> acks,
                                     std::span<const typename D::Bool> done) {
  typename D::Bool all(true);
  for (std::size_t k = 0; k < acks.size(); ++k) all = all && acks[k] == epoch && done[k];
  const typename D::Int next = num::select(epoch == kEpochs - 1, typename D::Int(0), epoch + 1);
  return {all, num::select(all, next, epoch)};
}

template <class D>
EpochControllerT<D> epoch_controller_rule(const EpochControllerT<D>& s, const typename D::Int& env_epoch,
                                          const typename D::Bool& at_waypoint) {
  const typename D::Bool accept = env_epoch != s.ack;
  return {num::select(accept, env_epoch, s.ack), num::select(accept, typename D::Bool(false), s.done || at_waypoint)};
}

#define SWARMCHECK_HANDSHAKE_RULES(D)                                                                          \
  template HandshakeStepT<D> environment_handshake_rule<D>(const HandshakeStateT<D>&, const D::Bool&);        \
  template D::Bool all_arrived_rule<D>(std::size_t, const std::function<D::Bool(std::size_t)>&);                \
  template EpochStepT<D> epoch_environment_rule<D>(const D::Int&, std::span<const D::Int>,                     \
                                                   std::span<const D::Bool>);                                   \
  template EpochControllerT<D> epoch_controller_rule<D>(const EpochControllerT<D>&, const D::Int&, const D::Bool&);
SWARMCHECK_HANDSHAKE_RULES(num::Concrete)
SWARMCHECK_HANDSHAKE_RULES(num::Symbolic)
#undef SWARMCHECK_HANDSHAKE_RULES

HandshakeStep environment_handshake(HandshakeState s, bool all_arrived) {
  const HandshakeStepT<num::Concrete> r =
      environment_handshake_rule<num::Concrete>({s.flag == 1, s.on_destination_output == 1}, all_arrived);
  return {r.plan, HandshakeState{r.next.flag ? 1 : 0, r.next.output ? 1 : 0}};
}

}  // namespace swarmcheck::exploration
