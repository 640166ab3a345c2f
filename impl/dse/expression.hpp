#pragma once
// The constraint language of a DSE configuration: one boolean expression per entry of
// `parameterConstraints` or `objectiveConstraints`, as INTO-CPS writes them (Python-like):
//
//   expr    := or
//   or      := and { ("or" | "||") and }
//   and     := not { ("and" | "&&") not }
//   not     := ("not" | "!") not | compare
//   compare := sum [ ("<" | "<=" | ">" | ">=" | "==" | "!=") sum ]   (no chains: a < b < c is refused)
//   sum     := product { ("+" | "-") product }
//   product := unary { ("*" | "/") unary }
//   unary   := ("-" | "+") unary | primary
//   primary := number | 'text' | "text" | true | false | True | False | name
//            | ("abs" | "min" | "max") "(" sum { "," sum } ")" | "(" expr ")"
//   name    := [A-Za-z_][A-Za-z0-9_.]*  or  {FMU}.instance.variable  (INTO-CPS's form)
//
// Types are checked when parsing (numbers, booleans, text; text compares with == and != only),
// so a constraint that parses never fails when evaluated. Every error names the column.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace swarmcheck::dse {

enum class ValueType { number, boolean, text };

struct Value {
  ValueType type = ValueType::number;
  double number = 0;
  bool boolean = false;
  std::string text;

  static Value of_number(double v) { return Value{ValueType::number, v, false, {}}; }
  static Value of_bool(bool v) { return Value{ValueType::boolean, 0, v, {}}; }
  static Value of_text(std::string v) { return Value{ValueType::text, 0, false, std::move(v)}; }
};

// The type of a name, or nullopt when the name is unknown (then `known_names` are listed).
using NameTypes = std::function<std::optional<ValueType>(const std::string& name)>;
// The value of a name that NameTypes knew.
using NameValues = std::function<Value(const std::string& name)>;

class Expression {
 public:
  // `where` prefixes every error, e.g. "dse.json: parameterConstraints[0]"; the error's place is
  // "<where>, column N" and its message quotes the text (around column N, when it is long).
  static Expression parse(const std::string& text, const NameTypes& types, const std::string& where,
                          const std::string& known_names);

  bool evaluate(const NameValues& values) const;
  const std::string& text() const { return text_; }
  // Every name the expression reads, in order of first appearance.
  const std::vector<std::string>& names() const { return names_; }

  enum class Op : uint8_t {
    number, text, boolean, name, neg, logical_not, add, sub, mul, div, lt, le, gt, ge, eq, ne,
    logical_and, logical_or, abs, min, max
  };
  struct Node {
    Op op = Op::number;
    ValueType type = ValueType::number;
    double number = 0;
    std::string text;               // text literal or name
    std::vector<int32_t> children;  // indices into nodes_
  };

 private:
  friend class Parser;
  Value eval(int32_t node, const NameValues& values) const;

  std::string text_;
  std::vector<Node> nodes_;
  int32_t root_ = -1;
  std::vector<std::string> names_;
};

}  // namespace swarmcheck::dse
