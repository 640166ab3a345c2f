#include "spec/util/sym.hpp"

#include <cmath>
#include <unordered_set>

namespace swarmcheck::sym {
namespace {

NodePtr make(Op op, Sort sort, std::vector<NodePtr> args) {
  auto n = std::make_shared<Node>();
  n->op = op;
  n->sort = sort;
  n->args = std::move(args);
  return n;
}

NodePtr real_literal(double v) {
  auto n = std::make_shared<Node>();
  n->op = Op::literal;
  n->sort = Sort::real;
  n->real = v;
  return n;
}

NodePtr int_literal(int64_t v, Sort sort) {
  auto n = std::make_shared<Node>();
  n->op = Op::literal;
  n->sort = sort;
  n->integer = v;
  return n;
}

NodePtr variable(std::string name, Sort sort) {
  auto n = std::make_shared<Node>();
  n->op = Op::variable;
  n->sort = sort;
  n->name = std::move(name);
  return n;
}

// Folds an operation on real literals with the double operation the concrete code performs.
Real real_op(Op op, const Real& a, const Real& b, double (*f)(double, double)) {
  if (a.is_literal() && b.is_literal()) return Real(f(a.literal(), b.literal()));
  return Real(make(op, Sort::real, {a.node(), b.node()}));
}

Real real_op(Op op, const Real& a, double (*f)(double)) {
  if (a.is_literal()) return Real(f(a.literal()));
  return Real(make(op, Sort::real, {a.node()}));
}

Bool real_cmp(Op op, const Real& a, const Real& b, bool (*f)(double, double)) {
  if (a.is_literal() && b.is_literal()) return Bool(f(a.literal(), b.literal()));
  return Bool(make(op, Sort::boolean, {a.node(), b.node()}));
}

Int int_op(Op op, const Int& a, const Int& b, int64_t (*f)(int64_t, int64_t)) {
  if (a.is_literal() && b.is_literal()) return Int(int_literal(f(a.literal(), b.literal()), Sort::integer));
  return Int(make(op, Sort::integer, {a.node(), b.node()}));
}

Bool int_cmp(Op op, const Int& a, const Int& b, bool (*f)(int64_t, int64_t)) {
  if (a.is_literal() && b.is_literal()) return Bool(f(a.literal(), b.literal()));
  return Bool(make(op, Sort::boolean, {a.node(), b.node()}));
}

}  // namespace

const char* to_string(Op op) {
  switch (op) {
    case Op::literal: return "literal";
    case Op::variable: return "variable";
    case Op::neg: return "neg";
    case Op::add: return "+";
    case Op::sub: return "-";
    case Op::mul: return "*";
    case Op::div: return "/";
    case Op::abs: return "abs";
    case Op::sqrt: return "sqrt";
    case Op::exp: return "exp";
    case Op::cos: return "cos";
    case Op::sin: return "sin";
    case Op::atan2: return "atan2";
    case Op::remainder: return "remainder";
    case Op::pow: return "pow";
    case Op::fmin: return "fmin";
    case Op::lt: return "<";
    case Op::le: return "<=";
    case Op::gt: return ">";
    case Op::ge: return ">=";
    case Op::eq: return "==";
    case Op::ne: return "!=";
    case Op::is_nan: return "is_nan";
    case Op::not_: return "not";
    case Op::and_: return "and";
    case Op::or_: return "or";
    case Op::select: return "select";
    case Op::draw: return "draw";
    case Op::to_real: return "to_real";
    case Op::call: return "call";
    case Op::function: return "function";
  }
  return "?";
}

Real::Real(double v) : n_(real_literal(v)) {}
Real Real::var(std::string name) { return Real(variable(std::move(name), Sort::real)); }
Bool::Bool(bool v) : n_(int_literal(v ? 1 : 0, Sort::boolean)) {}
Bool Bool::var(std::string name) { return Bool(variable(std::move(name), Sort::boolean)); }
Int::Int(int32_t v) : n_(int_literal(v, Sort::integer)) {}
Int Int::var(std::string name) { return Int(variable(std::move(name), Sort::integer)); }
Int Int::draw(const Int& n, std::string site) {
  auto d = std::make_shared<Node>();
  d->op = Op::draw;
  d->sort = Sort::integer;
  d->name = std::move(site);
  d->args = {n.node()};
  return Int(NodePtr(std::move(d)));
}

Real operator-(const Real& a) { return real_op(Op::neg, a, [](double x) { return -x; }); }
Real operator+(const Real& a, const Real& b) { return real_op(Op::add, a, b, [](double x, double y) { return x + y; }); }
Real operator-(const Real& a, const Real& b) { return real_op(Op::sub, a, b, [](double x, double y) { return x - y; }); }
Real operator*(const Real& a, const Real& b) { return real_op(Op::mul, a, b, [](double x, double y) { return x * y; }); }
Real operator/(const Real& a, const Real& b) { return real_op(Op::div, a, b, [](double x, double y) { return x / y; }); }
Bool operator<(const Real& a, const Real& b) { return real_cmp(Op::lt, a, b, [](double x, double y) { return x < y; }); }
Bool operator<=(const Real& a, const Real& b) { return real_cmp(Op::le, a, b, [](double x, double y) { return x <= y; }); }
Bool operator>(const Real& a, const Real& b) { return real_cmp(Op::gt, a, b, [](double x, double y) { return x > y; }); }
Bool operator>=(const Real& a, const Real& b) { return real_cmp(Op::ge, a, b, [](double x, double y) { return x >= y; }); }
Bool operator==(const Real& a, const Real& b) { return real_cmp(Op::eq, a, b, [](double x, double y) { return x == y; }); }
Bool operator!=(const Real& a, const Real& b) { return real_cmp(Op::ne, a, b, [](double x, double y) { return x != y; }); }

Int operator-(const Int& a) {
  if (a.is_literal()) return Int(int_literal(-a.literal(), Sort::integer));
  return Int(make(Op::neg, Sort::integer, {a.node()}));
}
Int operator+(const Int& a, const Int& b) { return int_op(Op::add, a, b, [](int64_t x, int64_t y) { return x + y; }); }
Int operator-(const Int& a, const Int& b) { return int_op(Op::sub, a, b, [](int64_t x, int64_t y) { return x - y; }); }
Int operator*(const Int& a, const Int& b) { return int_op(Op::mul, a, b, [](int64_t x, int64_t y) { return x * y; }); }
Bool operator<(const Int& a, const Int& b) { return int_cmp(Op::lt, a, b, [](int64_t x, int64_t y) { return x < y; }); }
Bool operator<=(const Int& a, const Int& b) { return int_cmp(Op::le, a, b, [](int64_t x, int64_t y) { return x <= y; }); }
Bool operator>(const Int& a, const Int& b) { return int_cmp(Op::gt, a, b, [](int64_t x, int64_t y) { return x > y; }); }
Bool operator>=(const Int& a, const Int& b) { return int_cmp(Op::ge, a, b, [](int64_t x, int64_t y) { return x >= y; }); }
Bool operator==(const Int& a, const Int& b) { return int_cmp(Op::eq, a, b, [](int64_t x, int64_t y) { return x == y; }); }
Bool operator!=(const Int& a, const Int& b) { return int_cmp(Op::ne, a, b, [](int64_t x, int64_t y) { return x != y; }); }

Bool operator!(const Bool& a) {
  if (a.is_literal()) return Bool(!a.literal());
  if (a.node()->op == Op::not_) return Bool(a.node()->args[0]);
  return Bool(make(Op::not_, Sort::boolean, {a.node()}));
}
Bool operator&&(const Bool& a, const Bool& b) {
  if (a.is_literal()) return a.literal() ? b : Bool(false);
  if (b.is_literal()) return b.literal() ? a : Bool(false);
  return Bool(make(Op::and_, Sort::boolean, {a.node(), b.node()}));
}
Bool operator||(const Bool& a, const Bool& b) {
  if (a.is_literal()) return a.literal() ? Bool(true) : b;
  if (b.is_literal()) return b.literal() ? Bool(true) : a;
  return Bool(make(Op::or_, Sort::boolean, {a.node(), b.node()}));
}
Bool operator==(const Bool& a, const Bool& b) {
  if (a.is_literal() && b.is_literal()) return Bool(a.literal() == b.literal());
  return Bool(make(Op::eq, Sort::boolean, {a.node(), b.node()}));
}
Bool operator!=(const Bool& a, const Bool& b) { return !(a == b); }

Real select(const Bool& c, const Real& a, const Real& b) {
  if (c.is_literal()) return c.literal() ? a : b;
  if (a.node() == b.node()) return a;
  return Real(make(Op::select, Sort::real, {c.node(), a.node(), b.node()}));
}
Bool select(const Bool& c, const Bool& a, const Bool& b) {
  if (c.is_literal()) return c.literal() ? a : b;
  if (a.node() == b.node()) return a;
  return Bool(make(Op::select, Sort::boolean, {c.node(), a.node(), b.node()}));
}
Int select(const Bool& c, const Int& a, const Int& b) {
  if (c.is_literal()) return c.literal() ? a : b;
  if (a.node() == b.node()) return a;
  return Int(make(Op::select, Sort::integer, {c.node(), a.node(), b.node()}));
}

Real abs(const Real& x) { return real_op(Op::abs, x, [](double v) { return std::fabs(v); }); }
Real sqrt(const Real& x) { return real_op(Op::sqrt, x, [](double v) { return std::sqrt(v); }); }
Real exp(const Real& x) { return real_op(Op::exp, x, [](double v) { return std::exp(v); }); }
Real cos(const Real& x) { return real_op(Op::cos, x, [](double v) { return std::cos(v); }); }
Real sin(const Real& x) { return real_op(Op::sin, x, [](double v) { return std::sin(v); }); }
Real atan2(const Real& y, const Real& x) {
  return real_op(Op::atan2, y, x, [](double a, double b) { return std::atan2(a, b); });
}
Real remainder(const Real& x, const Real& y) {
  return real_op(Op::remainder, x, y, [](double a, double b) { return std::remainder(a, b); });
}
Real pow(const Real& x, const Real& y) {
  return real_op(Op::pow, x, y, [](double a, double b) { return std::pow(a, b); });
}
Real fmin(const Real& x, const Real& y) {
  return real_op(Op::fmin, x, y, [](double a, double b) { return std::fmin(a, b); });
}
Bool is_nan(const Real& x) {
  if (x.is_literal()) return Bool(std::isnan(x.literal()));
  return Bool(make(Op::is_nan, Sort::boolean, {x.node()}));
}
Real to_real(const Int& x) {
  if (x.is_literal()) return Real(static_cast<double>(x.literal()));
  return Real(make(Op::to_real, Sort::real, {x.node()}));
}

namespace {

template <class T>
T marked(std::string_view fn, const T& x, Sort sort) {
  if (x.is_literal()) return x;
  auto n = std::make_shared<Node>();
  n->op = Op::call;
  n->sort = sort;
  n->name = std::string(fn);
  n->args = {x.node()};
  return T(NodePtr(std::move(n)));
}

NodePtr applied(const std::string& name, const std::vector<Int>& args, Sort sort) {
  auto n = std::make_shared<Node>();
  n->op = Op::function;
  n->sort = sort;
  n->name = name;
  for (const Int& a : args) n->args.push_back(a.node());
  return n;
}

// Every node under the roots once, children before parents (iterative: DAGs of many robots are deep).
std::vector<const Node*> post_order(const std::vector<NodePtr>& roots) {
  std::vector<const Node*> out;
  std::unordered_set<const Node*> seen;
  std::vector<std::pair<const Node*, bool>> stack;
  for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({it->get(), false});
  while (!stack.empty()) {
    auto [n, expanded] = stack.back();
    if (expanded) {
      stack.pop_back();
      out.push_back(n);
      continue;
    }
    if (!seen.insert(n).second) {
      stack.pop_back();
      continue;
    }
    stack.back().second = true;
    for (auto it = n->args.rbegin(); it != n->args.rend(); ++it)
      if (!seen.count(it->get())) stack.push_back({it->get(), false});
  }
  return out;
}

}  // namespace

Real mark(std::string_view fn, const Real& x) { return marked(fn, x, Sort::real); }
Bool mark(std::string_view fn, const Bool& x) { return marked(fn, x, Sort::boolean); }
Int mark(std::string_view fn, const Int& x) { return marked(fn, x, Sort::integer); }

Real real_function(const std::string& name, const std::vector<Int>& args) {
  return Real(applied(name, args, Sort::real));
}
Bool bool_function(const std::string& name, const std::vector<Int>& args) {
  return Bool(applied(name, args, Sort::boolean));
}
Int int_function(const std::string& name, const std::vector<Int>& args) {
  return Int(applied(name, args, Sort::integer));
}

std::vector<std::string> called_functions(const std::vector<NodePtr>& roots) {
  std::vector<std::string> out;
  std::unordered_set<std::string> seen;
  for (const Node* n : post_order(roots))
    if (n->op == Op::call && seen.insert(n->name).second) out.push_back(n->name);
  return out;
}

std::vector<NodePtr> calls_of(const std::vector<NodePtr>& roots, std::string_view fn) {
  // Post-order gives raw pointers; the shared pointers are found again from their parents.
  std::unordered_map<const Node*, NodePtr> owner;
  for (const NodePtr& r : roots) owner.emplace(r.get(), r);
  std::vector<NodePtr> out;
  for (const Node* n : post_order(roots)) {
    for (const NodePtr& a : n->args) owner.emplace(a.get(), a);
  }
  for (const Node* n : post_order(roots))
    if (n->op == Op::call && n->name == fn) out.push_back(owner.at(n));
  return out;
}

std::vector<NodePtr> variables(const std::vector<NodePtr>& roots) {
  std::vector<NodePtr> out;
  std::unordered_set<const Node*> seen;
  std::vector<NodePtr> stack(roots.rbegin(), roots.rend());
  while (!stack.empty()) {
    NodePtr n = std::move(stack.back());
    stack.pop_back();
    if (!seen.insert(n.get()).second) continue;
    if (n->op == Op::variable) out.push_back(n);
    for (auto it = n->args.rbegin(); it != n->args.rend(); ++it) stack.push_back(*it);
  }
  return out;
}

}  // namespace swarmcheck::sym
