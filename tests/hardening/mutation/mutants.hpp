#pragma once
// The mutants of the mutation test: byte flips, truncation and line edits for any file, JSON
// mutants made from a token list with JSON paths, UMDES .fsm mutants made from its fields; each
// set drawn from a seeded generator, so a seed always gives the same mutants.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <initializer_list>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "tests/hardening/mutation/text.hpp"

namespace swarmcheck::testing::mutation {

struct Mutant {
  std::string op;     // the mutation class
  std::string what;   // where and what changed, for the failure message
  std::string text;   // the mutated file
  bool bad = false;   // certainly invalid: must give status 2
  bool same = false;  // equivalent to the original: must give the original's status
};

using Rng = std::mt19937_64;

inline std::size_t below(Rng& rng, std::size_t n) {
  return n == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
}

template <class T>
inline const T& pick(Rng& rng, const std::vector<T>& v) {
  return v[below(rng, v.size())];
}

inline const std::string kFiftyDigits = "12345678901234567890123456789012345678901234567890";
inline const std::vector<std::string> kInvalidUtf8 = {
    "\xff", "\xc3", "\x80", "\xed\xa0\x80", "\xc0\xaf", "\xf8\x88\x80\x80\x80", "\xe2\x82"};

inline Mutant replace(const std::string& op, const std::string& text, std::size_t b, std::size_t e,
                      const std::string& with, const std::string& where) {
  Mutant m;
  m.op = op;
  m.text = text.substr(0, b) + with + text.substr(e);
  m.what = line_col(text, b) + where + ": '" + shown(text.substr(b, e - b), 60) + "' -> '" + shown(with, 60) + "'";
  return m;
}

inline Mutant byte_flip(Rng& rng, const std::string& text) {
  const std::size_t pos = below(rng, text.size());
  const int bit = static_cast<int>(below(rng, 8));
  std::string t = text;
  t[pos] = static_cast<char>(static_cast<unsigned char>(t[pos]) ^ (1u << bit));
  Mutant m = replace("byte_flip", text, pos, pos + 1, t.substr(pos, 1), " bit " + std::to_string(bit));
  return m;
}

inline Mutant truncation(Rng& rng, const std::string& text, std::size_t keep_below) {
  const std::size_t cut = below(rng, keep_below);
  Mutant m;
  m.op = "truncate";
  m.text = text.substr(0, cut);
  m.what = "cut at byte " + std::to_string(cut) + " (" + line_col(text, cut) + ") of " + std::to_string(text.size()) +
           ", last bytes kept '" + shown(text.substr(cut >= 30 ? cut - 30 : 0, std::min<std::size_t>(cut, 30))) + "'";
  return m;
}

inline Mutant delete_line(const std::string& text, const std::vector<Line>& lines, std::size_t i) {
  Mutant m;
  m.op = "delete_line";
  const std::size_t end = std::min(text.size(), lines[i].end + 1);
  m.text = text.substr(0, lines[i].begin) + text.substr(end);
  m.what = "line " + std::to_string(i + 1) + " '" +
           shown(text.substr(lines[i].begin, lines[i].end - lines[i].begin), 80) + "' deleted";
  return m;
}

inline Mutant duplicate_line(const std::string& text, const std::vector<Line>& lines, std::size_t i) {
  Mutant m;
  m.op = "duplicate_line";
  const std::string line = text.substr(lines[i].begin, lines[i].end - lines[i].begin) + "\n";
  m.text = text.substr(0, lines[i].begin) + line + text.substr(lines[i].begin);
  m.what = "line " + std::to_string(i + 1) + " '" + shown(line, 80) + "' twice";
  return m;
}

// JSON text as tokens, with the JSON path of every key and value, so a mutation can change one
// value in place and keep the rest of the file byte for byte. Lenient: it reads the shipped
// (valid) files only. For JSON Lines each line is one top-level value, `root` its 0-based line.
struct JTok {
  enum Kind { Str, Num, Lit, Open, Close, Colon, Comma } kind;
  std::size_t b, e;  // the token's bytes; for Open, e is the end of its matching Close
  bool key = false;
  std::string path = {};  // of the value (or of the member, for a key)
  std::size_t root = 0;
};

inline JTok jtok(JTok::Kind kind, std::size_t b, std::size_t e) {
  JTok t{kind, b, e};
  return t;
}

inline std::vector<JTok> json_tokens(const std::string& s) {
  std::vector<JTok> toks;
  std::size_t i = 0;
  while (i < s.size()) {
    const char c = s[i];
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
    } else if (c == '{' || c == '[') {
      toks.push_back(jtok(JTok::Open, i, i + 1));
      ++i;
    } else if (c == '}' || c == ']') {
      toks.push_back(jtok(JTok::Close, i, i + 1));
      ++i;
    } else if (c == ':') {
      toks.push_back(jtok(JTok::Colon, i, i + 1));
      ++i;
    } else if (c == ',') {
      toks.push_back(jtok(JTok::Comma, i, i + 1));
      ++i;
    } else if (c == '"') {
      std::size_t j = i + 1;
      while (j < s.size() && s[j] != '"') j += s[j] == '\\' ? 2 : 1;
      toks.push_back(jtok(JTok::Str, i, j + 1));
      i = j + 1;
    } else if (c == '-' || std::isdigit(static_cast<unsigned char>(c))) {
      std::size_t j = i + 1;
      while (j < s.size() && (std::isdigit(static_cast<unsigned char>(s[j])) || std::strchr("+-.eE", s[j]))) ++j;
      toks.push_back(jtok(JTok::Num, i, j));
      i = j;
    } else {
      std::size_t j = i;
      while (j < s.size() && std::isalnum(static_cast<unsigned char>(s[j]))) ++j;
      toks.push_back(jtok(JTok::Lit, i, std::max(j, i + 1)));
      i = std::max(j, i + 1);
    }
  }
  struct Frame {
    bool object;
    std::string path, key;
    std::size_t index = 0, open;
  };
  std::vector<Frame> stack;
  std::size_t root = 0;
  for (std::size_t k = 0; k < toks.size(); ++k) {
    JTok& t = toks[k];
    t.root = root;
    if (t.kind == JTok::Str && k + 1 < toks.size() && toks[k + 1].kind == JTok::Colon && !stack.empty() &&
        stack.back().object) {
      t.key = true;
      stack.back().key = s.substr(t.b + 1, t.e - t.b - 2);
      t.path = stack.back().path.empty() ? stack.back().key : stack.back().path + "." + stack.back().key;
      continue;
    }
    if (t.kind == JTok::Colon) continue;
    if (t.kind == JTok::Comma) {
      if (!stack.empty() && !stack.back().object) ++stack.back().index;
      continue;
    }
    if (t.kind == JTok::Close) {
      if (!stack.empty()) {
        toks[stack.back().open].e = t.e;
        stack.pop_back();
        if (stack.empty()) ++root;
      }
      continue;
    }
    std::string path;
    if (!stack.empty()) {
      const Frame& f = stack.back();
      path = f.object ? (f.path.empty() ? f.key : f.path + "." + f.key) : f.path + "[" + std::to_string(f.index) + "]";
    }
    t.path = path;
    if (t.kind == JTok::Open)
      stack.push_back({s[t.b] == '{', path, "", 0, k});
    else if (stack.empty())
      ++root;
  }
  return toks;
}

// Which keys a file of this kind cannot do without (removing one must be refused).
using Required = std::function<bool(std::size_t root, const std::string& path)>;

struct JsonKind {
  std::string name;
  bool lines;  // JSON Lines (a trace)
  Required required;
};

inline const std::vector<std::string> kWrongForNumber = {"\"x\"", "true", "null", "{}", "[]", "\"\"", "[1]"};
inline const std::vector<std::string> kWrongForString = {"0", "1.5", "true", "null", "[]", "{}", "-7"};
inline const std::vector<std::string> kWrongForLiteral = {"\"true\"", "1", "[]", "{}"};
inline const std::vector<std::string> kWrongForArray = {"1", "\"a\"", "{}", "null", "true"};
inline const std::vector<std::string> kWrongForObject = {"[]", "1", "\"o\"", "null", "false"};
inline const std::vector<std::string> kNanLike = {"NaN", "nan", "Infinity", "-Infinity", "inf", "0x10",  "+1",
                                                  ".5",  "1.",  "01",       "1e",        "--1", "1_000", "Ox1"};
inline const std::vector<std::string> kHuge = {"1e400",
                                               "-1e400",
                                               kFiftyDigits,
                                               "-" + kFiftyDigits,
                                               "1e200",
                                               "1e308",
                                               "1.7976931348623157e308",
                                               "4.9e-324",
                                               "18446744073709551616",
                                               "9223372036854775808",
                                               "2147483648",
                                               "4294967296",
                                               "-0",
                                               "-0.0"};

inline std::string nested(std::size_t depth) { return std::string(depth, '[') + "1" + std::string(depth, ']'); }

inline Mutant json_mutant(Rng& rng, const std::string& op, const std::string& text, const std::vector<JTok>& toks,
                          const JsonKind& kind) {
  auto of_kind = [&](auto pred) {
    std::vector<std::size_t> v;
    for (std::size_t k = 0; k < toks.size(); ++k)
      if (pred(toks[k])) v.push_back(k);
    return v;
  };
  auto at = [&](const JTok& t) {
    return " (line " + std::to_string(t.root + 1) + " " + (t.path.empty() ? "$" : t.path) + ")";
  };
  auto where = [&](const JTok& t) {
    return kind.lines ? at(t) : " (" + (t.path.empty() ? std::string("$") : t.path) + ")";
  };
  const auto values = of_kind([](const JTok& t) {
    return !t.key && t.kind != JTok::Close && t.kind != JTok::Colon && t.kind != JTok::Comma && !t.path.empty();
  });
  const auto numbers = of_kind([](const JTok& t) { return t.kind == JTok::Num; });
  const auto strings = of_kind([](const JTok& t) { return t.kind == JTok::Str; });
  const auto keys = of_kind([](const JTok& t) { return t.key; });
  const std::vector<Line> lines = lines_of(text);

  if (op == "byte_flip") {
    Mutant m = byte_flip(rng, text);
    // Every shipped file is ASCII: a byte of 0x80 or more alone is never UTF-8, so never JSON.
    for (std::size_t i = 0; i < m.text.size(); ++i)
      if (static_cast<unsigned char>(m.text[i]) >= 0x80) m.bad = true;
    return m;
  }
  if (op == "truncate") {
    if (!kind.lines) {
      Mutant m = truncation(rng, text, text.rfind('}'));
      m.bad = true;  // the top-level object is never closed
      return m;
    }
    Mutant m = truncation(rng, text, text.size());
    // Cut inside a line: the last record is not JSON. Cut between lines: a shorter trace; so is a
    // cut that drops only a line's newline (every reader takes a last line without one).
    const std::size_t cut = m.text.size();
    m.bad = cut == 0 || (text[cut - 1] != '\n' && (cut >= text.size() || text[cut] != '\n'));
    return m;
  }
  if (op == "delete_line") {
    const std::size_t i = below(rng, lines.size());
    Mutant m = delete_line(text, lines, i);
    m.bad = kind.lines && i == 0;  // a trace without its header
    return m;
  }
  if (op == "duplicate_line") {
    Mutant m = duplicate_line(text, lines, below(rng, lines.size()));
    m.bad = kind.lines;  // a second header, or a record whose step does not increase
    return m;
  }
  if (op == "huge_coordinate") {
    // A position whose square (a distance) overflows a double: refused, or used without printing
    // inf or nan (checked for every run that succeeds).
    auto positions = of_kind([](const JTok& t) {
      if (t.kind != JTok::Num) return false;
      for (const char* k : {"at[", "start[", "robots[", "waypoint[", "x_m", "y_m"})
        if (t.path.find(k) != std::string::npos) return true;
      return false;
    });
    const JTok& t = toks[pick(rng, positions.empty() ? numbers : positions)];
    return replace(op, text, t.b, t.e,
                   pick(rng, std::vector<std::string>{"1e155", "-1e200", "1e300", "-1.7976931348623157e308"}),
                   where(t));
  }
  if (op == "wrong_type") {
    const JTok& t = toks[pick(rng, values)];
    const auto& choices = t.kind == JTok::Num   ? kWrongForNumber
                          : t.kind == JTok::Str ? kWrongForString
                          : t.kind == JTok::Lit ? kWrongForLiteral
                          : text[t.b] == '['    ? kWrongForArray
                                                : kWrongForObject;
    Mutant m = replace("wrong_type", text, t.b, t.e, pick(rng, choices), where(t));
    m.bad = true;
    return m;
  }
  if (op == "number_to_string") {
    const JTok& t = toks[pick(rng, numbers)];
    Mutant m = replace("number_to_string", text, t.b, t.e, "\"" + text.substr(t.b, t.e - t.b) + "\"", where(t));
    m.bad = true;
    return m;
  }
  if (op == "huge_number") {
    const JTok& t = toks[pick(rng, numbers)];
    const std::string with = pick(rng, kHuge);
    Mutant m = replace("huge_number", text, t.b, t.e, with, where(t));
    m.bad = with == "1e400" || with == "-1e400";  // no double holds it; the rest may fit some field
    return m;
  }
  if (op == "negative") {
    const JTok& t = toks[pick(rng, numbers)];
    const std::string v = text.substr(t.b, t.e - t.b);
    const std::string with = below(rng, 2) ? "-1" : (v[0] == '-' ? "-" + v : "-" + v + "7");
    return replace("negative", text, t.b, t.e, with, where(t));
  }
  if (op == "nan_token") {
    const JTok& t = toks[pick(rng, below(rng, 4) ? numbers : values)];
    Mutant m = replace("nan_token", text, t.b, t.e, pick(rng, kNanLike), where(t));
    m.bad = true;  // none of these is JSON
    return m;
  }
  if (op == "deep_nesting") {
    const JTok& t = toks[pick(rng, values)];
    const std::size_t depth = pick(rng, std::vector<std::size_t>{3, 64, 1000, 100000});
    Mutant m = replace("deep_nesting", text, t.b, t.e, nested(depth), where(t));
    m.what = line_col(text, t.b) + where(t) + ": '" + shown(text.substr(t.b, t.e - t.b), 60) + "' -> [[[...1...]]] " +
             std::to_string(depth) + " deep";
    m.bad = true;  // no field of any format holds a list of lists of lists
    return m;
  }
  if (op == "remove_key") {
    const std::size_t k = pick(rng, keys);
    const JTok& key = toks[k];
    const JTok& value = toks[k + 2];
    std::size_t b = key.b, e = value.e;
    if (k + 3 < toks.size() && toks[k + 3].kind == JTok::Comma) {
      e = toks[k + 3].e;
    } else if (k > 0 && toks[k - 1].kind == JTok::Comma) {
      b = toks[k - 1].b;
    }
    Mutant m;
    m.op = "remove_key";
    m.text = text.substr(0, b) + text.substr(e);
    m.what = line_col(text, key.b) + where(key) + ": member '" + shown(text.substr(key.b, value.e - key.b), 80) +
             "' removed";
    m.bad = kind.required(key.root, key.path);
    return m;
  }
  if (op == "duplicate_key") {
    const std::size_t k = pick(rng, keys);
    const JTok& key = toks[k];
    const JTok& value = toks[k + 2];
    // The same member again, before the first; half the time with a different value.
    std::string member = text.substr(key.b, value.e - key.b);
    if (below(rng, 2) && value.kind == JTok::Num) member = text.substr(key.b, value.b - key.b) + "0";
    Mutant m;
    m.op = "duplicate_key";
    m.text = text.substr(0, key.b) + member + ", " + text.substr(key.b);
    m.what = line_col(text, key.b) + where(key) + ": member '" + shown(member, 80) + "' inserted before its twin";
    m.bad = true;
    return m;
  }
  if (op == "unknown_key") {
    const auto objects = of_kind([&](const JTok& t) { return t.kind == JTok::Open && text[t.b] == '{'; });
    const JTok& t = toks[pick(rng, objects)];
    const bool empty = text.find_first_not_of(" \t\r\n", t.b + 1) == t.e - 1;
    const std::string member = std::string("\"zz_unknown\": 1") + (empty ? "" : ", ");
    Mutant m = replace("unknown_key", text, t.b + 1, t.b + 1, member, where(t));
    m.bad = true;  // every format lists its keys exactly
    return m;
  }
  if (op == "invalid_utf8") {
    // Into a name when there is one (the value of a "name" key), else into any string.
    auto names = of_kind([&](const JTok& t) {
      return t.kind == JTok::Str && !t.key && t.path.size() >= 4 && t.path.compare(t.path.size() - 4, 4, "name") == 0;
    });
    const JTok& t = toks[pick(rng, names.empty() || below(rng, 3) == 0 ? strings : names)];
    const std::size_t at_byte = t.b + 1 + below(rng, t.e - t.b - 1);
    const std::string bytes = pick(rng, kInvalidUtf8);
    Mutant m = replace("invalid_utf8", text, at_byte, at_byte, bytes, where(t));
    m.what += " in string " + shown(text.substr(t.b, t.e - t.b), 60);
    m.bad = true;  // JSON text is UTF-8
    return m;
  }
  if (op == "escaped_control") {
    // Valid JSON for a control character: the message quoting it must escape it, not emit it.
    auto values_str = of_kind([](const JTok& t) { return t.kind == JTok::Str && !t.key; });
    const JTok& t = toks[pick(rng, values_str.empty() ? strings : values_str)];
    return replace(op, text, t.b, t.e,
                   pick(rng, std::vector<std::string>{"\"\\u001b[2J\\u001b[31mred\"", "\"two\\nlines\"",
                                                      "\"nul\\u0000byte\"", "\"cr\\rover\"", "\"bell\\u0007\""}),
                   where(t));
  }
  if (op == "unterminated_string") {
    // A string that never ends, running to the end of the file: the message must not quote it all.
    const JTok& t = toks[pick(rng, strings)];
    Mutant m;
    m.op = op;
    m.text = text.substr(0, t.b) + "\"" + std::string(5000, 'x');
    m.what = line_col(text, t.b) + where(t) + ": '" + shown(text.substr(t.b, t.e - t.b), 60) +
             "' -> '\"xxx...' (5000 x, no closing quote, end of file)";
    m.bad = true;
    return m;
  }
  if (op == "whitespace") {
    // Valid and equivalent: extra white space between tokens (only blanks within a JSON Lines line).
    std::string t = text;
    std::vector<std::size_t> spots;
    for (int n = 0; n < 6; ++n) spots.push_back(toks[below(rng, toks.size())].b);
    std::sort(spots.rbegin(), spots.rend());
    const std::vector<std::string> ws = kind.lines ? std::vector<std::string>{" ", "\t", "  \t "}
                                                   : std::vector<std::string>{" ", "\t", "\n", "\r\n", " \n\t "};
    for (std::size_t p : spots) t.insert(p, pick(rng, ws));
    Mutant m;
    m.op = "whitespace";
    m.text = t;
    m.what = "white space added before 6 tokens";
    m.same = true;
    return m;
  }
  ADD_FAILURE() << "unknown mutation " << op;
  return {};
}

inline const std::vector<std::string> kJsonOps = {
    "byte_flip",     "truncate",        "delete_line",  "duplicate_line",  "wrong_type",          "number_to_string",
    "huge_number",   "huge_coordinate", "negative",     "nan_token",       "deep_nesting",        "remove_key",
    "duplicate_key", "unknown_key",     "invalid_utf8", "escaped_control", "unterminated_string", "whitespace"};

// UMDES .fsm text: each whitespace-separated field with what it is, read from the (valid) original.
struct FTok {
  enum Kind { Count, StateName, Marked, NTrans, Event, Target, Attr, EventsWord, DeclEvent } kind;
  std::size_t b, e;
};

inline std::vector<FTok> fsm_tokens(const std::string& text, std::size_t& last_block_line_begin) {
  std::vector<FTok> toks;
  bool seen_count = false, in_events = false;
  long pending = -1;  // transitions still to come in this block; -1: expecting a state header
  for (const Line& l : lines_of(text)) {
    std::vector<std::pair<std::size_t, std::size_t>> f;
    for (std::size_t i = l.begin; i < l.end;) {
      while (i < l.end && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
      std::size_t j = i;
      while (j < l.end && !std::isspace(static_cast<unsigned char>(text[j]))) ++j;
      if (j > i) f.emplace_back(i, j);
      i = j;
    }
    if (f.empty()) continue;
    if (!seen_count) {
      toks.push_back({FTok::Count, f[0].first, f[0].second});
      seen_count = true;
    } else if (in_events) {
      toks.push_back({FTok::DeclEvent, f[0].first, f[0].second});
      for (std::size_t k = 1; k < f.size(); ++k) toks.push_back({FTok::Attr, f[k].first, f[k].second});
    } else if (pending <= 0 && text.compare(f[0].first, 6, "EVENTS") == 0 && f.size() == 1) {
      toks.push_back({FTok::EventsWord, f[0].first, f[0].second});
      in_events = true;
    } else if (pending <= 0) {
      toks.push_back({FTok::StateName, f[0].first, f[0].second});
      toks.push_back({FTok::Marked, f[1].first, f[1].second});
      toks.push_back({FTok::NTrans, f[2].first, f[2].second});
      pending = std::stol(text.substr(f[2].first, f[2].second - f[2].first));
      last_block_line_begin = l.begin;
    } else {
      toks.push_back({FTok::Event, f[0].first, f[0].second});
      toks.push_back({FTok::Target, f[1].first, f[1].second});
      for (std::size_t k = 2; k < f.size(); ++k) toks.push_back({FTok::Attr, f[k].first, f[k].second});
      --pending;
      last_block_line_begin = l.begin;
    }
  }
  return toks;
}

inline const std::vector<std::string> kFsmOps = {"byte_flip",
                                                 "truncate",
                                                 "delete_line",
                                                 "duplicate_line",
                                                 "bad_number",
                                                 "invalid_utf8_name",
                                                 "rename_invalid_utf8",
                                                 "bad_attribute",
                                                 "bad_target",
                                                 "crlf",
                                                 "spaces_and_blank_lines"};
inline const std::vector<std::string> kBadNumbers = {
    "1e400",       "-1",         kFiftyDigits,           "NaN", "inf", "x", "0x10", "2.5",
    "99999999999", "4294967297", "18446744073709551617", "1e9", "-0"};

inline Mutant fsm_mutant(Rng& rng, const std::string& op, const std::string& text) {
  std::size_t last_block_line = 0;
  const std::vector<FTok> toks = fsm_tokens(text, last_block_line);
  auto of = [&](std::initializer_list<FTok::Kind> kinds) {
    std::vector<FTok> v;
    for (const FTok& t : toks)
      if (std::find(kinds.begin(), kinds.end(), t.kind) != kinds.end()) v.push_back(t);
    return v;
  };
  const std::vector<Line> lines = lines_of(text);
  const std::size_t events_at = text.find("\nEVENTS");
  if (op == "byte_flip") return byte_flip(rng, text);
  if (op == "truncate") {
    Mutant m = truncation(rng, text, text.size());
    m.bad = m.text.size() <= last_block_line;  // at least one declared transition or state is gone
    return m;
  }
  if (op == "delete_line") {
    std::vector<std::size_t> nonblank;
    for (std::size_t i = 0; i < lines.size(); ++i)
      if (!blank(text, lines[i])) nonblank.push_back(i);
    const std::size_t i = pick(rng, nonblank);
    Mutant m = delete_line(text, lines, i);
    m.bad = events_at == std::string::npos || lines[i].begin <= events_at;  // a count no longer matches
    return m;
  }
  if (op == "duplicate_line") return duplicate_line(text, lines, below(rng, lines.size()));
  if (op == "bad_number") {
    const FTok t = pick(rng, of({FTok::Count, FTok::Marked, FTok::NTrans}));
    Mutant m = replace("bad_number", text, t.b, t.e, pick(rng, kBadNumbers), "");
    m.bad = true;
    return m;
  }
  if (op == "invalid_utf8_name") {
    const FTok t = pick(rng, of({FTok::StateName, FTok::Event, FTok::Target, FTok::DeclEvent}));
    const std::size_t at_byte = t.b + below(rng, t.e - t.b + 1);
    return replace("invalid_utf8_name", text, at_byte, at_byte, pick(rng, kInvalidUtf8),
                   " in name '" + text.substr(t.b, t.e - t.b) + "'");
  }
  if (op == "rename_invalid_utf8") {
    // A state (the initial one half the time) or an event renamed everywhere with bytes that are
    // not UTF-8: still a well-formed automaton, so 0, 1 or 2, but its name reaches the output.
    const bool state = below(rng, 3) != 0;
    const auto names =
        of(state ? std::initializer_list<FTok::Kind>{FTok::StateName} : std::initializer_list<FTok::Kind>{FTok::Event});
    const FTok t = state && below(rng, 2) ? names.front() : pick(rng, names);
    const std::string old_name = text.substr(t.b, t.e - t.b);
    const std::string bytes = pick(rng, kInvalidUtf8);
    const std::string new_name = old_name.substr(0, 1) + bytes + old_name.substr(1);
    Mutant m;
    m.op = op;
    std::size_t from = 0;
    for (const FTok& u : toks) {
      if (text.compare(u.b, u.e - u.b, old_name) != 0 || u.e - u.b != old_name.size()) continue;
      m.text += text.substr(from, u.b - from) + new_name;
      from = u.e;
    }
    m.text += text.substr(from);
    m.what =
        std::string(state ? "state" : "event") + " '" + old_name + "' renamed '" + shown(new_name) + "' everywhere";
    return m;
  }
  if (op == "bad_attribute") {
    const FTok t = pick(rng, of({FTok::Attr}));
    Mutant m = replace("bad_attribute", text, t.b, t.e,
                       pick(rng, std::vector<std::string>{"x", "C", "UC", "ucc", "c/uc", "\xff", "-"}), "");
    m.bad = true;
    return m;
  }
  if (op == "bad_target") {
    const FTok t = pick(rng, of({FTok::Target}));
    Mutant m =
        replace("bad_target", text, t.b, t.e, pick(rng, std::vector<std::string>{"42", "-1", kFiftyDigits, "s1x"}), "");
    m.bad = true;  // no state has that name
    return m;
  }
  if (op == "crlf") {
    Mutant m;
    m.op = "crlf";
    for (char c : text) m.text += c == '\n' ? std::string("\r\n") : std::string(1, c);
    m.what = "every line ending CRLF";
    m.same = true;
    return m;
  }
  if (op == "spaces_and_blank_lines") {
    Mutant m;
    m.op = "spaces_and_blank_lines";
    for (char c : text) {
      if (c == '\t')
        m.text += pick(rng, std::vector<std::string>{" ", "  ", " \t", "\t\t"});
      else if (c == '\n' && below(rng, 8) == 0)
        m.text += "\n\n";
      else
        m.text += c;
    }
    m.what = "tabs as runs of blanks, blank lines added";
    m.same = true;
    return m;
  }
  ADD_FAILURE() << "unknown mutation " << op;
  return {};
}

inline std::vector<Mutant> json_mutants(const std::string& text, const JsonKind& kind, std::size_t n,
                                        std::uint64_t seed) {
  Rng rng(seed);
  const auto toks = json_tokens(text);
  std::vector<Mutant> v;
  for (std::size_t i = 0; i < n; ++i) v.push_back(json_mutant(rng, kJsonOps[i % kJsonOps.size()], text, toks, kind));
  return v;
}

inline std::vector<Mutant> fsm_mutants(const std::string& text, std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<Mutant> v;
  for (std::size_t i = 0; i < n; ++i) v.push_back(fsm_mutant(rng, kFsmOps[i % kFsmOps.size()], text));
  return v;
}

}  // namespace swarmcheck::testing::mutation
