#pragma once
// The deposit around a centre (DESIGN.md A4, spec/SPEC.md section 2), tabulated once per run.
//
// A kernel holds deposit_amount(params, di, dj) for every offset of a window when the window is
// small, so that a step does not evaluate exp() per cell: a table of the same function of the
// same doubles has the same bits. Large windows compute each amount on demand.
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "spec/exploration/neighbourhood.hpp"
#include "spec/exploration/types.hpp"
#include "spec/util/num.hpp"

namespace swarmcheck::exploration {

template <class D>
struct DepositParamsT {
  typename D::Real max_ph, a1, epsilon, a2;
};

// The rules, once (deposit.cpp instantiates them for num::Concrete and num::Symbolic). The
// pheromone left at distance d (cells) from the deposit centre, max_ph exp(-d / a1) + epsilon / a2:
template <class D>
typename D::Real deposit_amount_rule(const DepositParamsT<D>& p, const typename D::Real& distance);
// The same at a cell (di, dj) away: d the Euclidean distance between the cell centres, computed
// in doubles from the offsets (they are whole numbers in both interpretations).
template <class D>
typename D::Real deposit_amount_at_rule(const DepositParamsT<D>& p, int32_t di, int32_t dj);
// A cell's pheromone after a deposit on it: current + amount (the grids' write).
template <class D>
typename D::Real deposited_pheromone_rule(const typename D::Real& current, const typename D::Real& amount);

inline double deposited_pheromone(double current, double amount) {
  return deposited_pheromone_rule<num::Concrete>(current, amount);
}

// The deposit kernel of a proof: deposit_amount_at_rule with symbolic parameters, one expression
// per offset (as the concrete kernel tables one double per offset).
struct SymbolicDepositKernel {
  DepositParamsT<num::Symbolic> params;
  sym::Real amount(int32_t di, int32_t dj) const {
    auto it = table_.find({di, dj});
    if (it == table_.end()) it = table_.emplace(std::make_pair(di, dj), deposit_amount_at_rule<num::Symbolic>(params, di, dj)).first;
    return it->second;
  }

 private:
  mutable std::map<std::pair<int32_t, int32_t>, sym::Real> table_;
};

class DepositKernel {
 public:
  DepositKernel() = default;
  DepositKernel(const Params& p, int32_t map_size);

  // max_ph * exp(-d / a1) + epsilon / a2 for a cell (di, dj) away from the centre.
  double amount(int32_t di, int32_t dj) const {
    if (table_.empty()) return deposit_amount(params_, di, dj);
    return table_[static_cast<std::size_t>((di + radius_) * side_ + (dj + radius_))];
  }
  // The tabled amounts of the row of offset di, by dj + radius(): row(di)[dj + radius()] is
  // amount(di, dj). nullptr when the window is not tabled (amount() computes each then).
  const double* row(int32_t di) const {
    if (table_.empty()) return nullptr;
    return &table_[static_cast<std::size_t>((di + radius_) * side_)];
  }
  int32_t radius() const { return radius_; }

 private:
  static constexpr int64_t kTableCellsMax = int64_t{1} << 16;
  Params params_{};
  int32_t radius_ = 0;
  int32_t side_ = 0;
  std::vector<double> table_;   // by (di + radius) * side + (dj + radius); empty: compute
};

}  // namespace swarmcheck::exploration
