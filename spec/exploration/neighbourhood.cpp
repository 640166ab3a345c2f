#include "spec/exploration/neighbourhood.hpp"

namespace swarmcheck::exploration {

template <class D>
WindowT<D> window_around_rule(const CellOf<D>& c, int32_t s_range, const typename D::Int& map_size) {
  using Int = typename D::Int;
  auto lo = [&](const Int& v) { return num::select(v - s_range < 0, Int(0), v - s_range); };
  auto hi = [&](const Int& v) { return num::select(v > map_size - 1 - s_range, map_size - 1, v + s_range); };
  constexpr const char* fn = "exploration::window_around";
  return WindowT<D>{num::traced(fn, lo(c[0])), num::traced(fn, hi(c[0])), num::traced(fn, lo(c[1])),
                    num::traced(fn, hi(c[1]))};
}

template WindowT<num::Concrete> window_around_rule<num::Concrete>(const CellIndex&, int32_t, const int32_t&);
template WindowT<num::Symbolic> window_around_rule<num::Symbolic>(const CellOf<num::Symbolic>&, int32_t, const sym::Int&);

}  // namespace swarmcheck::exploration
