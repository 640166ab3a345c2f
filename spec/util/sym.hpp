#pragma once
// Symbolic values: the second interpretation of the rules in spec/ (docs/proofs.md).
//
// A rule that an obligation is about is written once, as a template over a domain D (num.hpp):
// instantiated with num::Concrete (double, bool, int32_t) it is the code model/ and impl/ run;
// instantiated with num::Symbolic (the types below) it returns the rule as an expression DAG,
// which proofs/ translates to Z3 terms (FP, reals, integers) without restating the rule. This
// header knows nothing of Z3: spec/ stays pure.
//
// Nodes are immutable and shared; operations on two literals fold with the same double, bool or
// integer operation the concrete interpretation performs (so 1 / r is the double the code
// computes). Integer nodes hold small values (cell offsets, indices, epochs).
//
// Two kinds of node carry names:
//   call      the identity on its one argument, naming the spec function that computed it
//             (num::traced): what a property's expression passes through is read off its DAG
//             (called_functions), which is how proofs/ checks that an obligation reads the
//             functions the executed step calls
//   function  an uninterpreted function of integer arguments (a symbolic map's contents, say:
//             the obstacle flag of cell (i, j)), the same function for the same name
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace swarmcheck::sym {

enum class Sort : uint8_t { real, boolean, integer };

enum class Op : uint8_t {
  literal, variable,
  neg, add, sub, mul, div,                        // real; integer: neg, add, sub, mul
  abs, sqrt, exp, cos, sin, atan2, remainder, pow, fmin,   // real
  lt, le, gt, ge, eq, ne,                         // real or integer operands, boolean result
  is_nan,                                         // real operand
  not_, and_, or_,                                // boolean
  select,                                         // (condition, then, else), any sort
  draw,                                           // integer in [0, args[0]): a random draw
  to_real,                                        // an integer read as a real
  call,                                           // identity, naming the spec function (name)
  function,                                       // uninterpreted function (name) of integers
};

struct Node;
using NodePtr = std::shared_ptr<const Node>;

struct Node {
  Op op;
  Sort sort;
  double real = 0;          // literal value (real)
  int64_t integer = 0;      // literal value (integer, boolean 0/1)
  std::string name;         // variable name; draw: its purpose and site
  std::vector<NodePtr> args;
};

const char* to_string(Op op);

class Bool;
class Int;

class Real {
 public:
  Real() : Real(0.0) {}
  Real(double v);   // NOLINT(google-explicit-constructor): literals mix with symbols
  explicit Real(NodePtr n) : n_(std::move(n)) {}
  static Real var(std::string name);
  const NodePtr& node() const { return n_; }
  bool is_literal() const { return n_->op == Op::literal; }
  double literal() const { return n_->real; }

 private:
  NodePtr n_;
};

class Bool {
 public:
  Bool() : Bool(false) {}
  Bool(bool v);   // NOLINT(google-explicit-constructor)
  explicit Bool(NodePtr n) : n_(std::move(n)) {}
  static Bool var(std::string name);
  const NodePtr& node() const { return n_; }
  bool is_literal() const { return n_->op == Op::literal; }
  bool literal() const { return n_->integer != 0; }

 private:
  NodePtr n_;
};

class Int {
 public:
  Int() : Int(0) {}
  Int(int32_t v);   // NOLINT(google-explicit-constructor)
  explicit Int(NodePtr n) : n_(std::move(n)) {}
  static Int var(std::string name);
  // A uniform draw in [0, n): in a proof, any value of that range (the site names it).
  static Int draw(const Int& n, std::string site);
  const NodePtr& node() const { return n_; }
  bool is_literal() const { return n_->op == Op::literal; }
  int64_t literal() const { return n_->integer; }

 private:
  NodePtr n_;
};

Real operator-(const Real& a);
Real operator+(const Real& a, const Real& b);
Real operator-(const Real& a, const Real& b);
Real operator*(const Real& a, const Real& b);
Real operator/(const Real& a, const Real& b);
Bool operator<(const Real& a, const Real& b);
Bool operator<=(const Real& a, const Real& b);
Bool operator>(const Real& a, const Real& b);
Bool operator>=(const Real& a, const Real& b);
Bool operator==(const Real& a, const Real& b);
Bool operator!=(const Real& a, const Real& b);

Int operator-(const Int& a);
Int operator+(const Int& a, const Int& b);
Int operator-(const Int& a, const Int& b);
Int operator*(const Int& a, const Int& b);
Bool operator<(const Int& a, const Int& b);
Bool operator<=(const Int& a, const Int& b);
Bool operator>(const Int& a, const Int& b);
Bool operator>=(const Int& a, const Int& b);
Bool operator==(const Int& a, const Int& b);
Bool operator!=(const Int& a, const Int& b);

Bool operator!(const Bool& a);
Bool operator&&(const Bool& a, const Bool& b);
Bool operator||(const Bool& a, const Bool& b);
Bool operator==(const Bool& a, const Bool& b);
Bool operator!=(const Bool& a, const Bool& b);

Real select(const Bool& c, const Real& a, const Real& b);
Bool select(const Bool& c, const Bool& a, const Bool& b);
Int select(const Bool& c, const Int& a, const Int& b);

// What num::branch combines two symbolic results with.
inline Real merge(const Bool& c, const Real& a, const Real& b) { return select(c, a, b); }
inline Bool merge(const Bool& c, const Bool& a, const Bool& b) { return select(c, a, b); }
inline Int merge(const Bool& c, const Int& a, const Int& b) { return select(c, a, b); }

Real abs(const Real& x);
Real sqrt(const Real& x);
Real exp(const Real& x);
Real cos(const Real& x);
Real sin(const Real& x);
Real atan2(const Real& y, const Real& x);
Real remainder(const Real& x, const Real& y);
Real pow(const Real& x, const Real& y);
Real fmin(const Real& x, const Real& y);
Bool is_nan(const Real& x);
Real to_real(const Int& x);

// A call node: x, named as the result of the spec function fn (a literal stays a literal: it
// carries no symbol a property could depend on).
Real mark(std::string_view fn, const Real& x);
Bool mark(std::string_view fn, const Bool& x);
Int mark(std::string_view fn, const Int& x);

// The uninterpreted function `name` applied to integer arguments.
Real real_function(const std::string& name, const std::vector<Int>& args);
Bool bool_function(const std::string& name, const std::vector<Int>& args);
Int int_function(const std::string& name, const std::vector<Int>& args);

// The variables a set of expressions reads, each once, in first-seen order.
std::vector<NodePtr> variables(const std::vector<NodePtr>& roots);

// The spec functions a set of expressions passes through (the names of their call nodes), each
// once, in first-seen order.
std::vector<std::string> called_functions(const std::vector<NodePtr>& roots);

// The call nodes named fn under a set of roots, each once, children before parents.
std::vector<NodePtr> calls_of(const std::vector<NodePtr>& roots, std::string_view fn);

}  // namespace swarmcheck::sym
