#pragma once
// The two interpretations of a rule (docs/proofs.md, "one definition, two interpretations").
//
// A rule is a template over a domain D with three types, D::Real, D::Bool and D::Int, written
// with the operators and the functions of namespace num only (no `if` on a D::Bool: a branch is
// num::select, or num::branch when the concrete code should not evaluate the side not taken):
//   num::Concrete  double, bool, int32_t: the code model/ and impl/ run, bit for bit
//   num::Symbolic  sym::Real, sym::Bool, sym::Int: the same rule as an expression, for proofs/
// Each rule is defined in a spec .cpp file and instantiated there for both domains, so a change
// to the rule changes what runs and what is proved together.
#include <cmath>
#include <cstdint>
#include <type_traits>

#include "spec/util/sym.hpp"

namespace swarmcheck::num {

struct Concrete {
  using Real = double;
  using Bool = bool;
  using Int = int32_t;
};

struct Symbolic {
  using Real = sym::Real;
  using Bool = sym::Bool;
  using Int = sym::Int;
};

// Concrete.
inline double select(bool c, double a, double b) { return c ? a : b; }
inline bool select(bool c, bool a, bool b) { return c ? a : b; }
inline int32_t select(bool c, int32_t a, int32_t b) { return c ? a : b; }
inline int64_t select(bool c, int64_t a, int64_t b) { return c ? a : b; }
inline double abs(double x) { return std::fabs(x); }
inline double sqrt(double x) { return std::sqrt(x); }
inline double exp(double x) { return std::exp(x); }
inline double cos(double x) { return std::cos(x); }
inline double sin(double x) { return std::sin(x); }
inline double atan2(double y, double x) { return std::atan2(y, x); }
inline double remainder(double x, double y) { return std::remainder(x, y); }
inline double pow(double x, double y) { return std::pow(x, y); }
inline double fmin(double x, double y) { return std::fmin(x, y); }
inline bool is_nan(double x) { return std::isnan(x); }
inline double to_real(int32_t x) { return static_cast<double>(x); }
inline double to_real(int64_t x) { return static_cast<double>(x); }

// Symbolic.
using sym::select;
inline sym::Real abs(const sym::Real& x) { return sym::abs(x); }
inline sym::Real sqrt(const sym::Real& x) { return sym::sqrt(x); }
inline sym::Real exp(const sym::Real& x) { return sym::exp(x); }
inline sym::Real cos(const sym::Real& x) { return sym::cos(x); }
inline sym::Real sin(const sym::Real& x) { return sym::sin(x); }
inline sym::Real atan2(const sym::Real& y, const sym::Real& x) { return sym::atan2(y, x); }
inline sym::Real remainder(const sym::Real& x, const sym::Real& y) { return sym::remainder(x, y); }
inline sym::Real pow(const sym::Real& x, const sym::Real& y) { return sym::pow(x, y); }
inline sym::Real fmin(const sym::Real& x, const sym::Real& y) { return sym::fmin(x, y); }
inline sym::Bool is_nan(const sym::Real& x) { return sym::is_nan(x); }
inline sym::Real to_real(const sym::Int& x) { return sym::to_real(x); }

// A branch whose sides are computed by two functions returning the same type. The concrete
// code evaluates only the side taken (the hot path stays lazy); the symbolic one builds both
// and selects. For aggregates, `merge(c, a, b)` combines two results field by field.
template <class F, class G>
auto branch(bool c, F&& then_f, G&& else_f) {
  return c ? then_f() : else_f();
}
template <class F, class G>
auto branch(const sym::Bool& c, F&& then_f, G&& else_f) {
  if (c.is_literal()) return c.literal() ? then_f() : else_f();
  return merge(c, then_f(), else_f());
}

// A rule's result named as that rule's (sym.hpp, call nodes): the identity in the concrete
// domain, compiled away; in the symbolic one a node that lets proofs/ read off which spec
// functions a property's expression passes through.
template <class T>
constexpr const T& traced(const char* /*fn*/, const T& x) {
  return x;
}
inline sym::Real traced(const char* fn, const sym::Real& x) { return sym::mark(fn, x); }
inline sym::Bool traced(const char* fn, const sym::Bool& x) { return sym::mark(fn, x); }
inline sym::Int traced(const char* fn, const sym::Int& x) { return sym::mark(fn, x); }

// An effect on a state taken when c holds: `effect(state)`. The concrete code runs it only then;
// the symbolic one runs it on a copy and merges the copy back, field by field
// (`merge(c, changed, state)`, found by argument-dependent lookup for the state's type).
template <class S, class F>
void when(bool c, S& state, F&& effect) {
  if (c) effect(state);
}
template <class S, class F>
void when(const sym::Bool& c, S& state, F&& effect) {
  if (c.is_literal()) {
    if (c.literal()) effect(state);
    return;
  }
  S changed = state;
  effect(changed);
  state = merge(c, changed, state);
}
// The same for an effect with a result: c ? effect(state) : otherwise.
template <class S, class F, class T>
T when_else(bool c, S& state, F&& effect, const T& otherwise) {
  return c ? static_cast<T>(effect(state)) : otherwise;
}
template <class S, class F, class T>
T when_else(const sym::Bool& c, S& state, F&& effect, const T& otherwise) {
  if (c.is_literal()) return c.literal() ? static_cast<T>(effect(state)) : otherwise;
  S changed = state;
  const T r = effect(changed);
  state = merge(c, changed, state);
  return select(c, r, otherwise);
}

// True for the concrete domain (for the few places that must assert on concrete values only).
template <class D>
inline constexpr bool is_concrete = std::is_same_v<D, Concrete>;

}  // namespace swarmcheck::num
