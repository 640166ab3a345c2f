#pragma once
// Two things nlohmann's parser accepts that a user's file must not contain, found in one pass
// over the text before and after parsing:
//  - nesting deeper than kMaxJsonDepth: refused before parsing, so no reader recurses (parse,
//    copy, destroy, from_json) over an adversarial depth;
//  - a key twice in one object: nlohmann keeps the last silently, so a user's first value would
//    be ignored without a word.
// Both come back with the byte offset (1-based) of the offending bracket or key.
#include <cstddef>
#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

#include <nlohmann/json.hpp>

namespace swarmcheck::json_io {

inline constexpr int kMaxJsonDepth = 512;

struct JsonStructureFinding {
  std::size_t too_deep_at = 0;    // offset of the first bracket past kMaxJsonDepth (0: none)
  std::size_t duplicate_at = 0;   // offset of the first repeated key (0: none)
  std::string duplicate_key;
};

namespace detail {
// A key's text as the parser decodes it ("a" and "\u0061" are the same key).
inline std::string decoded_key(std::string_view raw_with_quotes) {
  if (raw_with_quotes.find('\\') == std::string_view::npos)
    return std::string(raw_with_quotes.substr(1, raw_with_quotes.size() - 2));
  const auto j = nlohmann::json::parse(raw_with_quotes, nullptr, false);
  return j.is_string() ? j.get<std::string>() : std::string(raw_with_quotes);
}
}  // namespace detail

// The scan stops at the first over-deep bracket; a duplicate is only recorded (the caller
// reports syntax errors, which nlohmann locates, before duplicates).
inline JsonStructureFinding scan_json_structure(std::string_view text) {
  JsonStructureFinding f;
  // One entry per open bracket: for an object, the keys seen so far.
  std::vector<std::unordered_set<std::string>> keys;
  std::vector<char> open;
  for (std::size_t k = 0; k < text.size(); ++k) {
    const char c = text[k];
    if (c == '"') {
      const std::size_t start = k;
      for (++k; k < text.size() && text[k] != '"'; ++k)
        if (text[k] == '\\') ++k;
      if (k >= text.size()) break;   // unterminated: the parser reports it
      if (f.duplicate_at != 0 || open.empty() || open.back() != '{') continue;
      std::size_t next = k + 1;
      while (next < text.size() && (text[next] == ' ' || text[next] == '\t' || text[next] == '\n' || text[next] == '\r')) ++next;
      if (next >= text.size() || text[next] != ':') continue;   // a value, not a key
      std::string key = detail::decoded_key(text.substr(start, k - start + 1));
      if (!keys.back().insert(key).second) {
        f.duplicate_at = start + 1;
        f.duplicate_key = std::move(key);
      }
    } else if (c == '{' || c == '[') {
      if (open.size() >= static_cast<std::size_t>(kMaxJsonDepth)) {
        f.too_deep_at = k + 1;
        return f;
      }
      open.push_back(c);
      keys.emplace_back();
    } else if ((c == '}' || c == ']') && !open.empty()) {
      open.pop_back();
      keys.pop_back();
    }
  }
  return f;
}

}  // namespace swarmcheck::json_io
