#include "spec/exploration/decay.hpp"

#include <algorithm>

#include "spec/util/demand.hpp"

namespace swarmcheck::exploration {

template <class D>
typename D::Real evaporation_factor_rule(const typename D::Real& ertu, const typename D::Real& step_size) {
  const typename D::Real f = 1.0 - ertu * step_size;
  return num::traced("exploration::evaporation_factor_rule", num::select(0.0 < f, f, typename D::Real(0.0)));
}

template <class D>
typename D::Real thesis_evaporate_rule(const typename D::Real& ph, const typename D::Real& ertu_times_dt) {
  const typename D::Real after = ph - ertu_times_dt * ph;
  return num::traced("exploration::thesis_evaporate_rule", num::select(after < 0.0, typename D::Real(0.0), after));
}

template <class D>
typename D::Real decay_square_rule(const typename D::Real& p) {
  return p * p;
}

template <class D>
typename D::Real decay_step_rule(const typename D::Real& acc, const typename D::Real& p) {
  return acc * p;
}

template <class D>
DecayTableT<D> make_decay_table_rule(const typename D::Real& f) {
  DecayTableT<D> t;
  t.pow2[0] = num::traced("exploration::make_decay_table", f);
  for (std::size_t i = 1; i < t.pow2.size(); ++i)
    t.pow2[i] = num::traced("exploration::make_decay_table", decay_square_rule<D>(t.pow2[i - 1]));
  return t;
}

template <class D>
typename D::Real decay_factor_from_rule(const DecayTableT<D>& table, typename D::Real acc, uint64_t bits,
                                        std::size_t first_bit) {
  for (std::size_t i = first_bit; bits != 0; ++i, bits >>= 1)
    if (bits & 1U) acc = num::traced("exploration::decay_factor", decay_step_rule<D>(acc, table.pow2[i]));
  return acc;
}

template <class D>
typename D::Real decay_factor_rule(const DecayTableT<D>& table, int64_t k) {
  return decay_factor_from_rule<D>(table, typename D::Real(1.0), static_cast<uint64_t>(k), 0);
}

template <class D>
typename D::Real decayed_pheromone_rule(const typename D::Real& value, const typename D::Real& factor) {
  return num::traced("exploration::decayed_pheromone_rule", value * factor);
}

#define SWARMCHECK_DECAY_RULES(D)                                                                           \
  template D::Real evaporation_factor_rule<D>(const D::Real&, const D::Real&);                              \
  template D::Real thesis_evaporate_rule<D>(const D::Real&, const D::Real&);                                \
  template D::Real decay_square_rule<D>(const D::Real&);                                                    \
  template D::Real decay_step_rule<D>(const D::Real&, const D::Real&);                                      \
  template DecayTableT<D> make_decay_table_rule<D>(const D::Real&);                                         \
  template D::Real decay_factor_from_rule<D>(const DecayTableT<D>&, D::Real, uint64_t, std::size_t);        \
  template D::Real decay_factor_rule<D>(const DecayTableT<D>&, int64_t);                                    \
  template D::Real decayed_pheromone_rule<D>(const D::Real&, const D::Real&);
SWARMCHECK_DECAY_RULES(num::Concrete)
SWARMCHECK_DECAY_RULES(num::Symbolic)
#undef SWARMCHECK_DECAY_RULES

double thesis_evaporate(double ph, double ertu_times_dt) {
  return thesis_evaporate_rule<num::Concrete>(ph, ertu_times_dt);
}

void thesis_evaporate_each(double* first, std::size_t count, std::size_t stride_bytes, double ertu_times_dt) {
  auto* bytes = reinterpret_cast<unsigned char*>(first);
  for (std::size_t k = 0; k < count; ++k) {
    auto* v = reinterpret_cast<double*>(bytes + k * stride_bytes);
    *v = thesis_evaporate_rule<num::Concrete>(*v, ertu_times_dt);
  }
}

double evaporation_factor(const Params& p) {
  const double f = evaporation_factor_rule<num::Concrete>(p.ertu, p.step_size);
  SWARM_DEMAND(f >= 0.0 && f <= 1.0);
  return f;
}

DecayTable make_decay_table(double f) {
  SWARM_DEMAND(f >= 0.0 && f <= 1.0);
  return make_decay_table_rule<num::Concrete>(f);
}

double decay_factor(const DecayTable& table, int64_t k) {
  SWARM_DEMAND(k >= 0);
  return decay_factor_rule<num::Concrete>(table, k);
}

double decay_factor_from(const DecayTable& table, double acc, uint64_t bits, std::size_t first_bit) {
  return decay_factor_from_rule<num::Concrete>(table, acc, bits, first_bit);
}

}  // namespace swarmcheck::exploration
