// The constraint language: precedence, types, INTO-CPS names, and errors that name the column.
#include <cstdlib>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <map>

#include "impl/dse/expression.hpp"
#include "impl/dse/format.hpp"
#include "spec/util/input_error.hpp"

using namespace swarmcheck;
using namespace swarmcheck::dse;

namespace {

// One seed for every run (an RC_PARAMS in the environment wins): CI and a developer see the
// same cases.
const bool kSeededDseExpressionTest = [] { return ::setenv("RC_PARAMS", "seed=17", 0) == 0; }();

const std::map<std::string, Value>& names() {
  static const std::map<std::string, Value> n{
      {"a1", Value::of_number(0.5)}, {"a2", Value::of_number(2)}, {"rule", Value::of_text("thesis")},
      {"{Environment}.EnvironmentInstance.ertu_perc", Value::of_number(0.07)}};
  return n;
}

Expression parse(const std::string& text) {
  return Expression::parse(
      text,
      [](const std::string& n) -> std::optional<ValueType> {
        const auto it = names().find(n);
        if (it == names().end()) return std::nullopt;
        return it->second.type;
      },
      "c.json: parameterConstraints[0]", "a1, a2, rule");
}

bool eval(const std::string& text) {
  return parse(text).evaluate([](const std::string& n) { return names().at(n); });
}

std::string expression_error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(Expression, ArithmeticBindsTighterThanComparisonThanNotThanAndThanOr) {
  EXPECT_TRUE(eval("1 + 2 * 3 == 7"));
  EXPECT_TRUE(eval("(1 + 2) * 3 == 9"));
  EXPECT_TRUE(eval("10 / 4 - 1 == 1.5"));
  EXPECT_TRUE(eval("-a1 < 0 and -(-a1) == a1"));
  EXPECT_TRUE(eval("not a1 > a2"));
  EXPECT_TRUE(eval("a1 > a2 or a1 < a2 and a2 == 2"));    // or(false, and(true, true))
  EXPECT_FALSE(eval("(a1 > a2 or a1 < a2) and a2 == 3"));
  EXPECT_TRUE(eval("true && !false || False"));
  EXPECT_TRUE(eval("1e-3 < .5 and 2.5E2 == 250"));
}

TEST(Expression, IntoCpsNamesTextAndFunctions) {
  EXPECT_TRUE(eval("{Environment}.EnvironmentInstance.ertu_perc == 0.07 and 2 * {Environment}.EnvironmentInstance.ertu_perc < 0.15"));
  EXPECT_TRUE(eval("rule == 'thesis' and rule != \"stochastic\""));
  EXPECT_TRUE(eval("min(a1, a2, 3) == 0.5 and max(a1, a2) == 2 and abs(-a2) == 2"));
  const Expression e = parse("a2 > a1 and a1 > 0 and rule == 'x'");
  EXPECT_EQ(e.names(), (std::vector<std::string>{"a2", "a1", "rule"}));
}

TEST(Expression, ErrorsNameTheColumnAndQuoteTheConstraintOnOneLine) {
  EXPECT_EQ(expression_error_of("a1 < )"),
            "c.json: parameterConstraints[0], column 6: expected a number, a name or '(', got ')' in \"a1 < )\"");
  EXPECT_NE(expression_error_of("a1 + ").find("column 6: expected a number, a name or '(', got 'end of text'"), std::string::npos);
  EXPECT_NE(expression_error_of("a1 < a2 < 3").find("column 9: chained comparisons are not supported"), std::string::npos);
  EXPECT_NE(expression_error_of("foo > 1").find("column 1: unknown name 'foo' (known: a1, a2, rule)"), std::string::npos);
  EXPECT_NE(expression_error_of("a1 and a2").find("column 4: 'and' needs a boolean, got a number"), std::string::npos);
  EXPECT_NE(expression_error_of("rule < 'x'").find("column 6: '<' needs a number, got text"), std::string::npos);
  EXPECT_NE(expression_error_of("rule == 1").find("'==' compares text with a number"), std::string::npos);
  EXPECT_NE(expression_error_of("a1 + 2").find("column 1: expected a boolean expression"), std::string::npos);
  EXPECT_NE(expression_error_of("rule == 'thesis").find("column 9: text starting here has no closing quote"), std::string::npos);
  EXPECT_NE(expression_error_of("a1 # 2").find("column 4: unexpected character '#'"), std::string::npos);
  EXPECT_NE(expression_error_of("(a1 > 1").find("expected ')' to close the '(' at column 1"), std::string::npos);
  EXPECT_NE(expression_error_of("abs(a1, a2) > 0").find("abs() takes exactly one argument"), std::string::npos);
  EXPECT_NE(expression_error_of("a1 > 0 a2").find("column 8: expected an operator or the end, got 'a2'"), std::string::npos);
}

RC_GTEST_PROP(Expression, ComparisonOfPrintedNumbersEvaluatesAsInCpp, (double a, double b, int op)) {
  RC_PRE(std::isfinite(a) && std::isfinite(b));
  const char* ops[] = {"<", "<=", ">", ">=", "==", "!="};
  const int k = ((op % 6) + 6) % 6;
  const std::string text = "(" + number_text(a) + ") " + ops[k] + " (" + number_text(b) + ")";
  const bool want = k == 0 ? a < b : k == 1 ? a <= b : k == 2 ? a > b : k == 3 ? a >= b : k == 4 ? a == b : a != b;
  RC_ASSERT(eval(text) == want);
}

namespace {
std::string repeated(const std::string& x, int n) {
  std::string out;
  for (int k = 0; k < n; ++k) out += x;
  return out;
}
}  // namespace

TEST(Expression, NestingBeyond256LevelsIsRefusedWithTheColumnInsteadOfOverflowingTheStack) {
  for (const std::string& deep :
       {repeated("(", 5000) + "1" + repeated(")", 5000) + " > 0", repeated("not ", 50000) + "(1 > 0)",
        "1" + repeated(" + 1", 50000) + " > 0", repeated("-", 50000) + "1 > 0",
        repeated("abs(", 5000) + "1" + repeated(")", 5000) + " > 0", repeated("min(1, ", 5000) + "1" + repeated(")", 5000) + " > 0"}) {
    const std::string error = expression_error_of(deep);
    EXPECT_NE(error.find("c.json: parameterConstraints[0], column "), std::string::npos) << error.substr(0, 200);
    EXPECT_NE(error.find("nested deeper than 256 levels"), std::string::npos) << error.substr(0, 200);
    EXPECT_LT(error.size(), 300U) << "the constraint is quoted around the column, not whole";
  }
  // 200 levels of each kind still parse and evaluate (a1 is 0.5).
  EXPECT_TRUE(eval(repeated("(", 200) + "a1" + repeated(")", 200) + " > 0"));
  EXPECT_TRUE(eval(repeated("not ", 200) + "(a1 > 0)"));
  EXPECT_TRUE(eval("a1" + repeated(" + 1", 200) + " > 200"));
  EXPECT_TRUE(eval(repeated("abs(", 200) + "a1" + repeated(")", 200) + " > 0"));
}
