#include "spec/exploration/decay.hpp"

#include <algorithm>

#include "spec/util/demand.hpp"

namespace swarmcheck::exploration {

template <class D>
typename D::Real evaporation_factor_rule(const typename D::Real& ertu, const typename D::Real& step_size) {
  const typename D::Real f = 1.0 - ertu * step_size;
  return num::select(0.0 < f, f, typename D::Real(0.0));
}

template <class D>
typename D::Real thesis_evaporate_rule(const typename D::Real& ph, const typename D::Real& ertu_times_dt) {
  const typename D::Real after = ph - ertu_times_dt * ph;
  return num::select(after < 0.0, typename D::Real(0.0), after);
}

template double thesis_evaporate_rule<num::Concrete>(const double&, const double&);
template sym::Real thesis_evaporate_rule<num::Symbolic>(const sym::Real&, const sym::Real&);

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

template double evaporation_factor_rule<num::Concrete>(const double&, const double&);
template sym::Real evaporation_factor_rule<num::Symbolic>(const sym::Real&, const sym::Real&);

double evaporation_factor(const Params& p) {
  const double f = evaporation_factor_rule<num::Concrete>(p.ertu, p.step_size);
  SWARM_DEMAND(f >= 0.0 && f <= 1.0);
  return f;
}

DecayTable make_decay_table(double f) {
  SWARM_DEMAND(f >= 0.0 && f <= 1.0);
  DecayTable t;
  t.pow2[0] = f;
  for (std::size_t i = 1; i < t.pow2.size(); ++i) t.pow2[i] = t.pow2[i - 1] * t.pow2[i - 1];
  return t;
}

double decay_factor(const DecayTable& table, int64_t k) {
  SWARM_DEMAND(k >= 0);
  double acc = 1.0;
  auto bits = static_cast<uint64_t>(k);
  for (std::size_t i = 0; bits != 0; ++i, bits >>= 1)
    if (bits & 1U) acc *= table.pow2[i];
  return acc;
}

}  // namespace swarmcheck::exploration
