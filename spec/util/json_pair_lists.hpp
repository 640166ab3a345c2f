#pragma once
// The fast path of a reader of big JSON documents whose bulk is a few top-level lists of number
// pairs (a scenario's robots and obstacles: 10^6 robots are 14 MB, and a DOM of them costs about
// a second to build and free).
//
// extract_pair_lists reads the named top-level members' lists [[a, b], ...] straight into
// vectors and returns the rest of the text, the same document with each of those lists replaced
// by []. It gives up (nullopt) on anything but the plain case: an escaped key, a list that is not
// of pairs of plain numbers, an integer where T is an integer type out of T's range, a float
// for an integer T, a number out of a double's range, a name seen twice, any syntax it does not
// expect. The caller then reads the whole text the ordinary way, which gives every error its
// usual message: this path never reports one itself.
//
// Why the rest stands for the whole document: the replaced spans are values of top-level members
// as a JSON tokenizer sees them, provided the text before them is a valid prefix (strings are
// skipped exactly as JSON tokenizes them), and the lists put back are valid values of depth 2
// without keys. So when the rest reads without error, the whole text reads without error, to the
// same values, and the lists hold what a DOM reader would have converted: numbers are read as
// nlohmann reads them (an integer literal as an integer, then converted; others as the correctly
// rounded double, which std::from_chars and strtod both give).
#include <array>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace swarmcheck::json_io {

// A top-level member to read: its name and where its list goes. `found` tells whether the text
// had it (if not, `out` is left as it was).
template <class T>
struct PairList {
  std::string_view name;
  std::vector<std::array<T, 2>>* out;
  bool found = false;
};

namespace pair_lists_detail {

inline bool is_ws(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

inline std::size_t skip_ws(std::string_view t, std::size_t p) {
  while (p < t.size() && is_ws(t[p])) ++p;
  return p;
}

// Past the string starting at t[p] == '"' (npos if unterminated); `plain`: no escape in it.
inline std::size_t skip_string(std::string_view t, std::size_t p, bool& plain) {
  plain = true;
  for (++p; p < t.size(); ++p) {
    if (t[p] == '"') return p + 1;
    if (t[p] == '\\') {
      plain = false;
      ++p;
    }
  }
  return std::string_view::npos;
}

// Past the value starting at t[p]; only its extent matters (the rest's reader checks it).
inline std::size_t skip_value(std::string_view t, std::size_t p) {
  bool plain = true;
  if (p >= t.size()) return std::string_view::npos;
  if (t[p] == '"') return skip_string(t, p, plain);
  if (t[p] == '[' || t[p] == '{') {
    std::size_t depth = 0;
    while (p < t.size()) {
      const char c = t[p];
      if (c == '"') {
        p = skip_string(t, p, plain);
        if (p == std::string_view::npos) return p;
        continue;
      }
      if (c == '[' || c == '{') ++depth;
      if ((c == ']' || c == '}') && --depth == 0) return p + 1;
      ++p;
    }
    return std::string_view::npos;
  }
  while (p < t.size() && !is_ws(t[p]) && t[p] != ',' && t[p] != '}' && t[p] != ']') ++p;
  return p;
}

// The JSON number at t[p], exactly as a DOM reader converts it to T; npos if it is not the plain
// case. JSON grammar: -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?
template <class T>
std::size_t read_number(std::string_view t, std::size_t p, T& out) {
  const std::size_t begin = p, n = t.size();
  auto digit = [&](std::size_t q) { return q < n && t[q] >= '0' && t[q] <= '9'; };
  if (p < n && t[p] == '-') ++p;
  if (!digit(p)) return std::string_view::npos;
  if (t[p] == '0') ++p;
  else
    while (digit(p)) ++p;
  bool integer = true;
  if (p < n && t[p] == '.') {
    integer = false;
    if (!digit(++p)) return std::string_view::npos;
    while (digit(p)) ++p;
  }
  if (p < n && (t[p] == 'e' || t[p] == 'E')) {
    integer = false;
    ++p;
    if (p < n && (t[p] == '+' || t[p] == '-')) ++p;
    if (!digit(p)) return std::string_view::npos;
    while (digit(p)) ++p;
  }
  const char* first = t.data() + begin;
  const char* last = t.data() + p;
  if (integer) {
    // nlohmann: an integer literal is an int64 (or uint64, or else a double: left to it).
    std::int64_t v = 0;
    const auto r = std::from_chars(first, last, v);
    if (r.ec != std::errc() || r.ptr != last) return std::string_view::npos;
    if constexpr (std::is_integral_v<T>) {
      if (v < std::numeric_limits<T>::min() || v > std::numeric_limits<T>::max()) return std::string_view::npos;
    }
    out = static_cast<T>(v);
    return p;
  }
  if constexpr (std::is_integral_v<T>) {
    return std::string_view::npos;   // "expected an integer": the DOM reader's message
  } else {
    double v = 0;
    const auto r = std::from_chars(first, last, v);
    if (r.ec != std::errc() || r.ptr != last) return std::string_view::npos;
    out = static_cast<T>(v);
    return p;
  }
}

// The list of pairs at t[p] == '[' into out; past it, or npos if it is not the plain case.
template <class T>
std::size_t read_pair_list(std::string_view t, std::size_t p, std::vector<std::array<T, 2>>& out) {
  out.clear();
  if (p >= t.size() || t[p] != '[') return std::string_view::npos;
  p = skip_ws(t, p + 1);
  if (p < t.size() && t[p] == ']') return p + 1;
  for (;;) {
    if (p >= t.size() || t[p] != '[') return std::string_view::npos;
    std::array<T, 2> pair{};
    for (std::size_t k = 0; k < 2; ++k) {
      p = read_number(t, skip_ws(t, p + 1), pair[k]);
      if (p == std::string_view::npos) return p;
      p = skip_ws(t, p);
      if (p >= t.size() || t[p] != (k == 0 ? ',' : ']')) return std::string_view::npos;
    }
    out.push_back(pair);
    p = skip_ws(t, p + 1);
    if (p >= t.size()) return std::string_view::npos;
    if (t[p] == ']') return p + 1;
    if (t[p] != ',') return std::string_view::npos;
    p = skip_ws(t, p + 1);
  }
}

// Reads the value at t[p] into the list named `key` if there is one; past the value or npos.
template <class T, class... More>
std::size_t read_member(std::string_view t, std::size_t p, std::string_view key, bool& replaced, PairList<T>& list,
                        PairList<More>&... more) {
  if (key == list.name) {
    if (list.found) return std::string_view::npos;   // twice: the DOM reader names the repeat
    list.found = true;
    replaced = true;
    return read_pair_list(t, p, *list.out);
  }
  if constexpr (sizeof...(More) > 0) return read_member(t, p, key, replaced, more...);
  else
    return skip_value(t, p);
}

}  // namespace pair_lists_detail

template <class... T>
std::optional<std::string> extract_pair_lists(std::string_view text, PairList<T>&... lists) {
  namespace d = pair_lists_detail;
  constexpr auto npos = std::string_view::npos;
  std::string rest;
  std::size_t copied = 0;   // text[0, copied) is in rest
  std::size_t p = d::skip_ws(text, 0);
  if (p >= text.size() || text[p] != '{') return std::nullopt;
  p = d::skip_ws(text, p + 1);
  if (p < text.size() && text[p] == '}') return std::string(text);
  for (;;) {
    if (p >= text.size() || text[p] != '"') return std::nullopt;
    bool plain = true;
    const std::size_t key_end = d::skip_string(text, p, plain);
    if (key_end == npos) return std::nullopt;
    const std::string_view key = plain ? text.substr(p + 1, key_end - p - 2) : std::string_view();
    p = d::skip_ws(text, key_end);
    if (p >= text.size() || text[p] != ':') return std::nullopt;
    const std::size_t value = d::skip_ws(text, p + 1);
    bool replaced = false;
    p = plain ? d::read_member(text, value, key, replaced, lists...) : d::skip_value(text, value);
    if (p == npos) return std::nullopt;
    if (replaced) {
      rest.append(text.substr(copied, value - copied)).append("[]");
      copied = p;
    }
    p = d::skip_ws(text, p);
    if (p >= text.size()) return std::nullopt;
    if (text[p] == '}') break;
    if (text[p] != ',') return std::nullopt;
    p = d::skip_ws(text, p + 1);
  }
  rest.append(text.substr(copied));
  return rest;
}

}  // namespace swarmcheck::json_io
