#include "proofs/obligations/translate.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <fmt/format.h>
#include <numbers>
#include <stdexcept>

namespace swarmcheck::proofs {
namespace {

using sym::Op;
using sym::Sort;

bool uninterpreted(Op op, RealTheory t) {
  switch (op) {
    case Op::exp: case Op::cos: case Op::sin: case Op::atan2: case Op::remainder: case Op::pow: return true;
    case Op::sqrt: return t == RealTheory::real;
    default: return false;
  }
}

}  // namespace

Translator::Translator(z3::context& ctx, RealTheory theory, bool consistency, unsigned int_bits)
    : ctx_(ctx), theory_(theory), consistency_(consistency), int_bits_(int_bits) {}

Translator::Translator(Session& session, RealTheory theory, bool consistency, unsigned int_bits)
    : ctx_(session.ctx()), session_reads_(&session.reads()), theory_(theory), consistency_(consistency),
      int_bits_(int_bits) {}

z3::expr Translator::variable(const std::string& name, Sort sort) {
  switch (sort) {
    case Sort::boolean: return ctx_.bool_const(name.c_str());
    case Sort::integer: return int_bits_ > 0 ? ctx_.bv_const(name.c_str(), int_bits_) : ctx_.int_const(name.c_str());
    case Sort::real:
      return theory_ == RealTheory::fp64 ? ctx_.fpa_const<64>(name.c_str()) : ctx_.real_const(name.c_str());
  }
  throw std::logic_error("sym: bad sort");
}

z3::expr Translator::real_literal(double v) {
  if (theory_ == RealTheory::fp64) {
    if (std::isnan(v)) return ctx_.fpa_nan(ctx_.fpa_sort<64>());
    return ctx_.fpa_val(v);
  }
  if (!std::isfinite(v)) throw std::invalid_argument(fmt::format("sym: the literal {} has no real value", v));
  // The exact value of the double: its FP numeral converted to a real, simplified to a rational.
  return z3::expr(ctx_, Z3_mk_fpa_to_real(ctx_, ctx_.fpa_val(v))).simplify();
}

// One application of an uninterpreted function: a fresh constant, its facts, and consistency
// with every earlier application of the same function.
z3::expr Translator::apply(Op op, const std::vector<z3::expr>& args) {
  const bool fp = theory_ == RealTheory::fp64;
  const z3::expr r = fp ? ctx_.fpa_const<64>(fmt::format("{}!{}", sym::to_string(op), fresh_).c_str())
                        : ctx_.real_const(fmt::format("{}!{}", sym::to_string(op), fresh_).c_str());
  ++fresh_;
  if (!fp) {
    const z3::expr zero = ctx_.real_val(0), one = ctx_.real_val(1);
    const z3::expr& x = args[0];
    switch (op) {
      case Op::sqrt: facts_.push_back(r >= 0 && z3::implies(x >= 0, r * r == x)); break;
      case Op::exp:
        facts_.push_back(r > 0 && z3::implies(x <= 0, r <= one) && z3::implies(x >= 0, r >= one) &&
                         z3::implies(x == 0, r == one));
        break;
      case Op::cos: case Op::sin: facts_.push_back(r >= -one && r <= one); break;
      case Op::atan2: {
        // The double nearest pi bounds what std::atan2 returns: [-pi_d, pi_d].
        const z3::expr pi = real_literal(std::numbers::pi), half = real_literal(std::numbers::pi / 2);
        const z3::expr& y = args[0];
        const z3::expr& xx = args[1];
        facts_.push_back(-pi <= r && r <= pi && z3::implies(y == 0 && xx > 0, r == 0) &&
                         z3::implies(y == 0 && xx < 0, r == pi) && z3::implies(y > 0 && xx == 0, r == half) &&
                         z3::implies(y < 0 && xx == 0, r == -half) &&
                         z3::implies(y > 0 && xx > 0, zero < r && r < half) &&
                         z3::implies(y > 0 && xx < 0, half < r && r < pi) &&
                         z3::implies(y < 0 && xx > 0, -half < r && r < zero) &&
                         z3::implies(y < 0 && xx < 0, -pi < r && r < -half));
        break;
      }
      case Op::remainder: {
        // x - r is a whole multiple of y, and |r| <= |y| / 2 (IEEE remainder).
        const z3::expr& y = args[1];
        const z3::expr k = ctx_.int_const(fmt::format("remainder_k!{}", fresh_).c_str());
        const z3::expr ay = z3::ite(y < 0, -y, y);
        facts_.push_back(2 * r <= ay && -ay <= 2 * r);
        if (y.is_numeral()) facts_.push_back(x - r == z3::to_real(k) * y);
        break;
      }
      default: break;
    }
  }
  for (const Application& a : apps_) {
    if (a.op != op || !consistency_) continue;
    z3::expr same = ctx_.bool_val(true);
    for (std::size_t k = 0; k < args.size(); ++k) same = same && (fp ? z3::fp_eq(a.args[k], args[k]) : a.args[k] == args[k]);
    facts_.push_back(z3::implies(same, fp ? z3::fp_eq(a.result, r) || (a.result.mk_is_nan() && r.mk_is_nan())
                                          : a.result == r));
  }
  apps_.push_back(Application{op, args, r});
  return r;
}

z3::expr Translator::arith(const sym::Node& n, const std::vector<z3::expr>& a) {
  const bool fp = theory_ == RealTheory::fp64 && n.sort != Sort::integer &&
                  (n.args.empty() || n.args[0]->sort == Sort::real);
  switch (n.op) {
    case Op::neg: return -a[0];
    case Op::add: return a[0] + a[1];
    case Op::sub: return a[0] - a[1];
    case Op::mul: return a[0] * a[1];
    case Op::div: {
      if (fp || a[1].is_numeral()) return a[0] / a[1];
      // Over the reals, a quotient by a term is a fresh real q with q b = a (b != 0): the
      // nonlinear solver handles products far better than division.
      // Z3 terms are hash-consed: one quotient per (dividend, divisor), however often the rule
      // computes it (epsilon / a2 in every robot's deposit).
      const auto key = std::make_pair(a[0].id(), a[1].id());
      for (const auto& [k, q] : quotients_)
        if (k == key) return q;
      const z3::expr q = ctx_.real_const(fmt::format("quotient!{}", fresh_++).c_str());
      facts_.push_back(z3::implies(a[1] != 0, q * a[1] == a[0]));
      quotients_.emplace_back(key, q);
      return q;
    }
    case Op::abs: return fp ? z3::abs(a[0]) : z3::ite(a[0] < 0, -a[0], a[0]);
    case Op::sqrt: return z3::sqrt(a[0], ctx_.fpa_rounding_mode());   // fp64 only
    case Op::fmin:
      if (fp) return z3::expr(ctx_, Z3_mk_fpa_min(ctx_, a[0], a[1]));
      return z3::ite(a[0] <= a[1], a[0], a[1]);
    case Op::lt: return a[0] < a[1];
    case Op::le: return a[0] <= a[1];
    case Op::gt: return a[0] > a[1];
    case Op::ge: return a[0] >= a[1];
    case Op::eq: return fp ? z3::fp_eq(a[0], a[1]) : a[0] == a[1];
    case Op::ne: return fp ? !z3::fp_eq(a[0], a[1]) : a[0] != a[1];
    case Op::is_nan: return theory_ == RealTheory::fp64 ? a[0].mk_is_nan() : ctx_.bool_val(false);
    case Op::not_: return !a[0];
    case Op::and_: return a[0] && a[1];
    case Op::or_: return a[0] || a[1];
    case Op::select: return z3::ite(a[0], a[1], a[2]);
    case Op::to_real:
      if (int_bits_ > 0) throw std::logic_error("sym: to_real of a bit-vector integer");
      if (theory_ == RealTheory::real) return z3::to_real(a[0]);
      return z3::expr(ctx_, Z3_mk_fpa_to_fp_signed(ctx_, ctx_.fpa_rounding_mode(), z3::int2bv(64, a[0]),
                                                    ctx_.fpa_sort<64>()));
    default: break;
  }
  throw std::logic_error(fmt::format("sym: no translation of {}", sym::to_string(n.op)));
}

z3::expr Translator::node(const sym::NodePtr& root) {
  // Iterative post-order: rules unrolled over many robots make deep DAGs.
  std::vector<std::pair<const sym::NodePtr*, bool>> stack{{&root, false}};
  while (!stack.empty()) {
    auto [np, expanded] = stack.back();
    const sym::Node& n = **np;
    if (memo_.count(&n)) { stack.pop_back(); continue; }
    const bool abstracted_call = n.op == Op::call && abstract_calls_.count(n.name);
    if (!expanded) {
      stack.back().second = true;
      if (!abstracted_call)
        for (const sym::NodePtr& a : n.args)
          if (!memo_.count(a.get())) stack.push_back({&a, false});
      continue;
    }
    stack.pop_back();
    std::vector<z3::expr> args;
    if (!abstracted_call)
      for (const sym::NodePtr& a : n.args) args.push_back(memo_.at(a.get()));
    z3::expr e(ctx_);
    if (abstracted_call) {
      reads_.insert(n.name);
      if (session_reads_) session_reads_->insert(n.name);
      const std::string name = fmt::format("{}!{}", n.name, fresh_++);
      e = n.sort == Sort::boolean ? ctx_.bool_const(name.c_str())
          : n.sort == Sort::integer
              ? (int_bits_ > 0 ? ctx_.bv_const(name.c_str(), int_bits_) : ctx_.int_const(name.c_str()))
              : (theory_ == RealTheory::fp64 ? ctx_.fpa_const<64>(name.c_str()) : ctx_.real_const(name.c_str()));
      facts_.push_back(abstract_calls_.at(n.name)(e));
      memo_.emplace(&n, e);
      keep_.push_back(*np);
      continue;
    }
    switch (n.op) {
      case Op::literal:
        if (n.sort == Sort::real) e = real_literal(n.real);
        else if (n.sort == Sort::boolean) e = ctx_.bool_val(n.integer != 0);
        else if (int_bits_ > 0) e = ctx_.bv_val(static_cast<int64_t>(n.integer), int_bits_);
        else e = ctx_.int_val(static_cast<int64_t>(n.integer));
        break;
      case Op::variable: e = variable(n.name, n.sort); break;
      case Op::call:
        e = args[0];
        reads_.insert(n.name);
        if (session_reads_) session_reads_->insert(n.name);
        break;
      case Op::function: {
        z3::sort_vector domain(ctx_);
        for (const z3::expr& a : args) domain.push_back(a.get_sort());
        z3::sort range = n.sort == Sort::boolean ? ctx_.bool_sort()
                         : n.sort == Sort::integer
                             ? (int_bits_ > 0 ? ctx_.bv_sort(int_bits_) : ctx_.int_sort())
                             : (theory_ == RealTheory::fp64 ? ctx_.fpa_sort<64>() : ctx_.real_sort());
        z3::expr_vector actual(ctx_);
        for (const z3::expr& a : args) actual.push_back(a);
        e = ctx_.function(n.name.c_str(), domain, range)(actual);
        break;
      }
      case Op::draw: {
        const std::string name = fmt::format("draw!{}!{}", n.name, fresh_++);
        e = int_bits_ > 0 ? ctx_.bv_const(name.c_str(), int_bits_) : ctx_.int_const(name.c_str());
        facts_.push_back(z3::implies(args[0] > 0, e >= 0 && e < args[0]));
        break;
      }
      default:
        if (abstract_ && n.sort == Sort::real && n.op != Op::select && n.op != Op::call) {
          const std::string name = fmt::format("abstract!{}!{}", sym::to_string(n.op), fresh_++);
          e = theory_ == RealTheory::fp64 ? ctx_.fpa_const<64>(name.c_str()) : ctx_.real_const(name.c_str());
        } else {
          e = uninterpreted(n.op, theory_) ? apply(n.op, args) : arith(n, args);
        }
    }
    memo_.emplace(&n, e);
    keep_.push_back(*np);
  }
  return memo_.at(root.get());
}

z3::expr Translator::side_conditions() const {
  z3::expr all = ctx_.bool_val(true);
  for (const z3::expr& f : facts_) all = all && f;
  return all;
}

z3::expr Translator::take_new_facts() {
  z3::expr all = ctx_.bool_val(true);
  for (; taken_ < facts_.size(); ++taken_) all = all && facts_[taken_];
  return all;
}

double model_double(const z3::model& m, const z3::expr& x) {
  const z3::expr v = m.eval(x, true);
  if (v.get_sort().sort_kind() == Z3_FLOATING_POINT_SORT) {
    if (m.eval(x.mk_is_nan(), true).is_true()) return std::nan("");
    const z3::expr bits = m.eval(x.mk_to_ieee_bv(), true);
    return std::bit_cast<double>(static_cast<uint64_t>(bits.get_numeral_uint64()));
  }
  if (v.is_numeral()) return std::stod(v.get_decimal_string(25));
  return std::nan("");
}

}  // namespace swarmcheck::proofs
