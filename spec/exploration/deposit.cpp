#include "spec/exploration/deposit.hpp"

#include <algorithm>
#include <cmath>

namespace swarmcheck::exploration {

template <class D>
typename D::Real deposit_amount_rule(const DepositParamsT<D>& p, const typename D::Real& distance) {
  return p.max_ph * num::exp(-distance / p.a1) + p.epsilon / p.a2;
}

template double deposit_amount_rule<num::Concrete>(const DepositParamsT<num::Concrete>&, const double&);
template sym::Real deposit_amount_rule<num::Symbolic>(const DepositParamsT<num::Symbolic>&, const sym::Real&);

double deposit_amount(const Params& p, int32_t di, int32_t dj) {
  const double d = std::sqrt(static_cast<double>(int64_t{di} * di + int64_t{dj} * dj));
  return deposit_amount_rule<num::Concrete>({p.max_ph, p.a1, p.epsilon, p.a2}, d);
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
