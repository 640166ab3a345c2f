#include "spec/exploration/deposit.hpp"

#include <algorithm>
#include <cmath>

namespace swarmcheck::exploration {

template <class D>
typename D::Real deposit_amount_rule(const DepositParamsT<D>& p, const typename D::Real& distance) {
  return num::traced("exploration::deposit_amount_rule", p.max_ph * num::exp(-distance / p.a1) + p.epsilon / p.a2);
}

template <class D>
typename D::Real deposit_amount_at_rule(const DepositParamsT<D>& p, int32_t di, int32_t dj) {
  const double d = std::sqrt(static_cast<double>(int64_t{di} * di + int64_t{dj} * dj));
  return deposit_amount_rule<D>(p, typename D::Real(d));
}

template <class D>
typename D::Real deposited_pheromone_rule(const typename D::Real& current, const typename D::Real& amount) {
  return num::traced("exploration::deposited_pheromone_rule", current + amount);
}

#define SWARMCHECK_DEPOSIT_RULES(D)                                                                 \
  template D::Real deposit_amount_rule<D>(const DepositParamsT<D>&, const D::Real&);                \
  template D::Real deposit_amount_at_rule<D>(const DepositParamsT<D>&, int32_t, int32_t);          \
  template D::Real deposited_pheromone_rule<D>(const D::Real&, const D::Real&);
SWARMCHECK_DEPOSIT_RULES(num::Concrete)
SWARMCHECK_DEPOSIT_RULES(num::Symbolic)
#undef SWARMCHECK_DEPOSIT_RULES

double deposit_amount(const Params& p, int32_t di, int32_t dj) {
  return deposit_amount_at_rule<num::Concrete>({p.max_ph, p.a1, p.epsilon, p.a2}, di, dj);
}

DepositKernel::DepositKernel(const Params& p, int32_t map_size) : params_(p) {
  // Offsets never exceed the map, whatever s_range says.
  const int64_t side = 2 * int64_t{std::min(p.s_range, map_size)} + 1;
  if (side * side > kTableCellsMax) return;
  radius_ = static_cast<int32_t>((side - 1) / 2);
  side_ = static_cast<int32_t>(side);
  table_.reserve(static_cast<std::size_t>(side * side));
  for (int32_t di = -radius_; di <= radius_; ++di)
    for (int32_t dj = -radius_; dj <= radius_; ++dj) table_.push_back(deposit_amount(p, di, dj));
}

}  // namespace swarmcheck::exploration
