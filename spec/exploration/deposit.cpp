#include "spec/exploration/deposit.hpp"

#include <algorithm>

namespace swarmcheck::exploration {

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
