#include "impl/dse/expression.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

#include "spec/util/input_error.hpp"

namespace swarmcheck::dse {
// Named rather than anonymous: Parser (a friend of Expression, so not internal) holds Tokens.
namespace expression_lexer {

enum class Tok { end, number, text, name, lparen, rparen, comma, op };

struct Token {
  Tok kind = Tok::end;
  std::string text;   // operator spelling, name, or text literal's content
  double number = 0;
  std::size_t column = 1;   // 1-based
};

std::string type_word(ValueType t) {
  switch (t) {
    case ValueType::number: return "a number";
    case ValueType::boolean: return "a boolean";
    case ValueType::text: return "text";
  }
  return "?";
}

bool name_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_' || c == '{'; }
bool name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.'; }

}  // namespace expression_lexer
using namespace expression_lexer;

// Recursive descent over a token list; builds Expression::nodes_ with types checked.
class Parser {
 public:
  Parser(const std::string& text, const NameTypes& types, const std::string& where,
         const std::string& known)
      : text_(text), types_(types), where_(where), known_(known) {}

  Expression run() {
    tokenize();
    Expression e;
    e.text_ = text_;
    out_ = &e;
    const int32_t root = parse_or();
    if (peek().kind != Tok::end) fail(peek().column, "expected an operator or the end, got '" + spelling(peek()) + "'");
    if (e.nodes_[root].type != ValueType::boolean)
      fail(1, "expected a boolean expression (a comparison, and/or/not), got " + type_word(e.nodes_[root].type));
    e.root_ = root;
    return e;
  }

 private:
  // One line, the constraint quoted after the column (the CLI prints a message as one line, with
  // control bytes escaped: a caret drawn under it on a line of its own came out as \x0A).
  [[noreturn]] void fail(std::size_t column, const std::string& what) const {
    throw InputError(where_ + ", column " + std::to_string(column), what + " in \"" + excerpt(column) + "\"");
  }
  // The constraint, or up to 30 characters either side of the column in a long one.
  std::string excerpt(std::size_t column) const {
    constexpr std::size_t kSide = 30;
    if (text_.size() <= 2 * kSide + 10) return text_;
    const std::size_t at = std::min(column - 1, text_.size());
    const std::size_t from = at > kSide ? at - kSide : 0;
    const std::size_t to = std::min(text_.size(), at + kSide);
    return (from > 0 ? "..." : "") + text_.substr(from, to - from) + (to < text_.size() ? "..." : "");
  }

  static std::string spelling(const Token& t) {
    switch (t.kind) {
      case Tok::end: return "end of text";
      case Tok::text: return "'" + t.text + "'";
      default: return t.text;
    }
  }

  void tokenize() {
    std::size_t k = 0;
    while (k < text_.size()) {
      const char c = text_[k];
      const std::size_t column = k + 1;
      if (std::isspace(static_cast<unsigned char>(c))) {
        ++k;
      } else if (std::isdigit(static_cast<unsigned char>(c)) ||
                 (c == '.' && k + 1 < text_.size() && std::isdigit(static_cast<unsigned char>(text_[k + 1])))) {
        k = read_number(k);
      } else if (c == '\'' || c == '"') {
        const std::size_t close = text_.find(c, k + 1);
        if (close == std::string::npos) fail(column, "text starting here has no closing quote");
        tokens_.push_back(Token{Tok::text, text_.substr(k + 1, close - k - 1), 0, column});
        k = close + 1;
      } else if (name_start(c)) {
        k = read_name(k);
      } else {
        k = read_punct(k);
      }
    }
    tokens_.push_back(Token{Tok::end, "", 0, text_.size() + 1});
  }

  std::size_t read_number(std::size_t k) {
    std::size_t e = k;
    while (e < text_.size() && (std::isdigit(static_cast<unsigned char>(text_[e])) || text_[e] == '.')) ++e;
    if (e < text_.size() && (text_[e] == 'e' || text_[e] == 'E')) {
      std::size_t x = e + 1;
      if (x < text_.size() && (text_[x] == '+' || text_[x] == '-')) ++x;
      if (x < text_.size() && std::isdigit(static_cast<unsigned char>(text_[x]))) {
        e = x;
        while (e < text_.size() && std::isdigit(static_cast<unsigned char>(text_[e]))) ++e;
      }
    }
    double v = 0;
    const auto r = std::from_chars(text_.data() + k, text_.data() + e, v);
    if (r.ec != std::errc() || r.ptr != text_.data() + e)
      fail(k + 1, "expected a number, got '" + text_.substr(k, e - k) + "'");
    tokens_.push_back(Token{Tok::number, text_.substr(k, e - k), v, k + 1});
    return e;
  }

  std::size_t read_name(std::size_t k) {
    std::size_t e = k;
    if (text_[k] == '{') {
      e = text_.find('}', k);
      if (e == std::string::npos) fail(k + 1, "'{' starts an INTO-CPS name but has no closing '}'");
      ++e;
    }
    while (e < text_.size() && name_char(text_[e])) ++e;
    tokens_.push_back(Token{Tok::name, text_.substr(k, e - k), 0, k + 1});
    return e;
  }

  std::size_t read_punct(std::size_t k) {
    static const char* two[] = {"<=", ">=", "==", "!=", "&&", "||"};
    for (const char* t : two)
      if (text_.compare(k, 2, t) == 0) {
        tokens_.push_back(Token{Tok::op, t, 0, k + 1});
        return k + 2;
      }
    const char c = text_[k];
    const std::string one(1, c);
    if (c == '(') tokens_.push_back(Token{Tok::lparen, one, 0, k + 1});
    else if (c == ')') tokens_.push_back(Token{Tok::rparen, one, 0, k + 1});
    else if (c == ',') tokens_.push_back(Token{Tok::comma, one, 0, k + 1});
    else if (std::string("<>+-*/!").find(c) != std::string::npos) tokens_.push_back(Token{Tok::op, one, 0, k + 1});
    else fail(k + 1, "unexpected character '" + one + "'");
    return k + 1;
  }

  const Token& peek() const { return tokens_[pos_]; }
  bool is_op(const Token& t, std::initializer_list<const char*> ops) const {
    if (!(t.kind == Tok::op || t.kind == Tok::name)) return false;
    return std::any_of(ops.begin(), ops.end(), [&](const char* o) { return t.text == o; });
  }

  // Parsing and evaluating recurse once per level: an expression nested deeper (parentheses,
  // prefix operators, or a long chain of one operator, a tree as deep as it is long) is refused
  // rather than allowed to overflow the stack (a 5 000-level constraint crashed `dse`).
  static constexpr int32_t kMaxDepth = 256;
  void too_deep() const {
    fail(tokens_[std::min(pos_, tokens_.size() - 1)].column,
         "nested deeper than " + std::to_string(kMaxDepth) + " levels (parentheses, operators or a chain of them)");
  }
  struct Deeper {
    explicit Deeper(Parser& p) : parser(p) {
      if (++parser.depth_ > kMaxDepth) parser.too_deep();
    }
    ~Deeper() { --parser.depth_; }
    Deeper(const Deeper&) = delete;
    Deeper& operator=(const Deeper&) = delete;
    Parser& parser;
  };

  int32_t add(Expression::Op op, ValueType type, std::vector<int32_t> children = {}) {
    int32_t depth = 1;
    for (int32_t c : children) depth = std::max(depth, 1 + node_depth_[static_cast<std::size_t>(c)]);
    if (depth > kMaxDepth) too_deep();
    node_depth_.push_back(depth);
    Expression::Node n;
    n.op = op;
    n.type = type;
    n.children = std::move(children);
    out_->nodes_.push_back(std::move(n));
    return static_cast<int32_t>(out_->nodes_.size() - 1);
  }
  ValueType type_of(int32_t node) const { return out_->nodes_[node].type; }

  void expect_type(int32_t node, ValueType want, std::size_t column, const std::string& context) const {
    if (type_of(node) != want)
      fail(column, context + " needs " + type_word(want) + ", got " + type_word(type_of(node)));
  }

  int32_t parse_or() {
    const Deeper deeper(*this);
    int32_t left = parse_and();
    while (is_op(peek(), {"or", "||"})) {
      const Token t = tokens_[pos_++];
      const int32_t right = parse_and();
      expect_type(left, ValueType::boolean, t.column, "'" + t.text + "'");
      expect_type(right, ValueType::boolean, t.column, "'" + t.text + "'");
      left = add(Expression::Op::logical_or, ValueType::boolean, {left, right});
    }
    return left;
  }

  int32_t parse_and() {
    int32_t left = parse_not();
    while (is_op(peek(), {"and", "&&"})) {
      const Token t = tokens_[pos_++];
      const int32_t right = parse_not();
      expect_type(left, ValueType::boolean, t.column, "'" + t.text + "'");
      expect_type(right, ValueType::boolean, t.column, "'" + t.text + "'");
      left = add(Expression::Op::logical_and, ValueType::boolean, {left, right});
    }
    return left;
  }

  int32_t parse_not() {
    if (is_op(peek(), {"not", "!"})) {
      const Token t = tokens_[pos_++];
      const Deeper deeper(*this);
      const int32_t inner = parse_not();
      expect_type(inner, ValueType::boolean, t.column, "'" + t.text + "'");
      return add(Expression::Op::logical_not, ValueType::boolean, {inner});
    }
    return parse_compare();
  }

  int32_t parse_compare() {
    using Op = Expression::Op;
    const int32_t left = parse_sum();
    if (!is_op(peek(), {"<", "<=", ">", ">=", "==", "!="})) return left;
    const Token t = tokens_[pos_++];
    const int32_t right = parse_sum();
    if (is_op(peek(), {"<", "<=", ">", ">=", "==", "!="}))
      fail(peek().column, "chained comparisons are not supported: join them with 'and'");
    const bool equality = t.text == "==" || t.text == "!=";
    if (type_of(left) != type_of(right))
      fail(t.column, "'" + t.text + "' compares " + type_word(type_of(left)) + " with " + type_word(type_of(right)));
    if (!equality) expect_type(left, ValueType::number, t.column, "'" + t.text + "'");
    const Op op = t.text == "<" ? Op::lt : t.text == "<=" ? Op::le : t.text == ">" ? Op::gt
                : t.text == ">=" ? Op::ge : t.text == "==" ? Op::eq : Op::ne;
    return add(op, ValueType::boolean, {left, right});
  }

  int32_t parse_sum() {
    int32_t left = parse_product();
    while (is_op(peek(), {"+", "-"})) {
      const Token t = tokens_[pos_++];
      const int32_t right = parse_product();
      expect_type(left, ValueType::number, t.column, "'" + t.text + "'");
      expect_type(right, ValueType::number, t.column, "'" + t.text + "'");
      left = add(t.text == "+" ? Expression::Op::add : Expression::Op::sub, ValueType::number, {left, right});
    }
    return left;
  }

  int32_t parse_product() {
    int32_t left = parse_unary();
    while (is_op(peek(), {"*", "/"})) {
      const Token t = tokens_[pos_++];
      const int32_t right = parse_unary();
      expect_type(left, ValueType::number, t.column, "'" + t.text + "'");
      expect_type(right, ValueType::number, t.column, "'" + t.text + "'");
      left = add(t.text == "*" ? Expression::Op::mul : Expression::Op::div, ValueType::number, {left, right});
    }
    return left;
  }

  int32_t parse_unary() {
    if (is_op(peek(), {"-", "+"})) {
      const Token t = tokens_[pos_++];
      const Deeper deeper(*this);
      const int32_t inner = parse_unary();
      expect_type(inner, ValueType::number, t.column, "unary '" + t.text + "'");
      return t.text == "-" ? add(Expression::Op::neg, ValueType::number, {inner}) : inner;
    }
    return parse_primary();
  }

  int32_t parse_call(const Token& fn) {
    using Op = Expression::Op;
    const Deeper deeper(*this);   // abs(abs(...)) recurses without passing through parse_or
    ++pos_;   // '('
    std::vector<int32_t> args;
    while (true) {
      const std::size_t column = peek().column;
      const int32_t a = parse_sum();
      expect_type(a, ValueType::number, column, fn.text + "()");
      args.push_back(a);
      if (peek().kind == Tok::comma) { ++pos_; continue; }
      if (peek().kind == Tok::rparen) { ++pos_; break; }
      fail(peek().column, "expected ',' or ')' in " + fn.text + "(), got '" + spelling(peek()) + "'");
    }
    if (fn.text == "abs" && args.size() != 1) fail(fn.column, "abs() takes exactly one argument");
    if (fn.text != "abs" && args.size() < 2) fail(fn.column, fn.text + "() takes at least two arguments");
    const Op op = fn.text == "abs" ? Op::abs : fn.text == "min" ? Op::min : Op::max;
    return add(op, ValueType::number, std::move(args));
  }

  int32_t parse_primary() {
    using Op = Expression::Op;
    const Token t = peek();
    switch (t.kind) {
      case Tok::number: {
        ++pos_;
        const int32_t n = add(Op::number, ValueType::number);
        out_->nodes_[n].number = t.number;
        return n;
      }
      case Tok::text: {
        ++pos_;
        const int32_t n = add(Op::text, ValueType::text);
        out_->nodes_[n].text = t.text;
        return n;
      }
      case Tok::lparen: {
        ++pos_;
        const int32_t inner = parse_or();
        if (peek().kind != Tok::rparen) fail(peek().column, "expected ')' to close the '(' at column " + std::to_string(t.column) + ", got '" + spelling(peek()) + "'");
        ++pos_;
        return inner;
      }
      case Tok::name: return parse_name(t);
      default: fail(t.column, "expected a number, a name or '(', got '" + spelling(t) + "'");
    }
  }

  int32_t parse_name(const Token& t) {
    using Op = Expression::Op;
    ++pos_;
    if (t.text == "true" || t.text == "True" || t.text == "false" || t.text == "False") {
      const int32_t n = add(Op::boolean, ValueType::boolean);
      out_->nodes_[n].number = (t.text == "true" || t.text == "True") ? 1 : 0;
      return n;
    }
    if ((t.text == "abs" || t.text == "min" || t.text == "max") && peek().kind == Tok::lparen) return parse_call(t);
    if (t.text == "and" || t.text == "or" || t.text == "not")
      fail(t.column, "expected an operand, got the operator '" + t.text + "'");
    const std::optional<ValueType> type = types_(t.text);
    if (!type) fail(t.column, "unknown name '" + t.text + "' (known: " + known_ + ")");
    const int32_t n = add(Op::name, *type);
    out_->nodes_[n].text = t.text;
    auto& names = out_->names_;
    if (std::find(names.begin(), names.end(), t.text) == names.end()) names.push_back(t.text);
    return n;
  }

  const std::string& text_;
  const NameTypes& types_;
  const std::string& where_;
  const std::string& known_;
  std::vector<Token> tokens_;
  std::size_t pos_ = 0;
  Expression* out_ = nullptr;
  int32_t depth_ = 0;                 // parse_or / prefix-operator recursion, now
  std::vector<int32_t> node_depth_;   // per node: the height of its subtree
};

Expression Expression::parse(const std::string& text, const NameTypes& types, const std::string& where,
                             const std::string& known_names) {
  return Parser(text, types, where, known_names).run();
}

bool Expression::evaluate(const NameValues& values) const {
  const Value v = eval(root_, values);
  return v.boolean;
}

Value Expression::eval(int32_t index, const NameValues& values) const {
  const Node& n = nodes_[index];
  const auto num = [&](std::size_t k) { return eval(n.children[k], values).number; };
  const auto boolean = [&](std::size_t k) { return eval(n.children[k], values).boolean; };
  switch (n.op) {
    case Op::number: return Value::of_number(n.number);
    case Op::text: return Value::of_text(n.text);
    case Op::boolean: return Value::of_bool(n.number != 0);
    case Op::name: return values(n.text);
    case Op::neg: return Value::of_number(-num(0));
    case Op::logical_not: return Value::of_bool(!boolean(0));
    case Op::add: return Value::of_number(num(0) + num(1));
    case Op::sub: return Value::of_number(num(0) - num(1));
    case Op::mul: return Value::of_number(num(0) * num(1));
    case Op::div: return Value::of_number(num(0) / num(1));
    case Op::lt: return Value::of_bool(num(0) < num(1));
    case Op::le: return Value::of_bool(num(0) <= num(1));
    case Op::gt: return Value::of_bool(num(0) > num(1));
    case Op::ge: return Value::of_bool(num(0) >= num(1));
    case Op::eq:
    case Op::ne: {
      const Value a = eval(n.children[0], values), b = eval(n.children[1], values);
      const bool same = a.type == ValueType::text ? a.text == b.text
                      : a.type == ValueType::boolean ? a.boolean == b.boolean : a.number == b.number;
      return Value::of_bool(n.op == Op::eq ? same : !same);
    }
    case Op::logical_and: return Value::of_bool(boolean(0) && boolean(1));
    case Op::logical_or: return Value::of_bool(boolean(0) || boolean(1));
    case Op::abs: return Value::of_number(std::fabs(num(0)));
    case Op::min:
    case Op::max: {
      double r = num(0);
      for (std::size_t k = 1; k < n.children.size(); ++k)
        r = n.op == Op::min ? std::min(r, num(k)) : std::max(r, num(k));
      return Value::of_number(r);
    }
  }
  return Value::of_bool(false);
}

}  // namespace swarmcheck::dse
