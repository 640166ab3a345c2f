#pragma once
// THE JSON reader: every JSON text swarmcheck reads (files, trace lines, journal lines, request
// bodies, FMU resources, messages between MPI ranks, the prover's report) goes through
// parse_json_text, so every input gets the same guarantees: nesting past kMaxJsonDepth refused
// before anything recurses over it, a key at most once per object, a NUL byte and a number no
// double holds refused, and every error an InputError at file:line:col. Keys a reader does not
// know are refused by from_json (hana records) or refuse_unknown_keys (hand-read objects).
// scripts/check-json-reader (ctest json_reader_check) fails when a source outside this file,
// json_structure.hpp and json_pair_lists.hpp calls nlohmann's parser itself.
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "spec/util/hana_json.hpp"
#include "spec/util/input_error.hpp"
#include "spec/util/json_structure.hpp"

namespace swarmcheck::json_io {

// "file:line:col" of the byte at offset `byte` (1-based) of text.
// first_line: the line number of text's first line (a JSON Lines record is one line of a file).
inline std::string text_position(const std::string& text, std::size_t byte, const std::string& file,
                                 int64_t first_line = 1) {
  int64_t line = first_line;
  std::size_t col = 1;
  for (std::size_t k = 0; k + 1 < byte && k < text.size(); ++k) {
    if (text[k] == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
  }
  return file + ":" + std::to_string(line) + ":" + std::to_string(col);
}

namespace detail {
// Builds the document nlohmann's DOM parser builds, but appends each member to its object instead
// of looking its key up first: ordered_json's lookup is a linear scan, so an object of N keys
// took O(N^2) to parse (65 536 region-entry events: 6 s; 200 000: 50 s). Keys are unique here:
// scan_json_structure refuses a repeated one. A syntax error or a number out of range is thrown
// as the DOM parser throws it.
class AppendingDomBuilder {
 public:
  explicit AppendingDomBuilder(Json& root) : root_(root) {}
  bool null() { return put(nullptr) != nullptr; }
  bool boolean(bool v) { return put(v) != nullptr; }
  bool number_integer(Json::number_integer_t v) { return put(v) != nullptr; }
  bool number_unsigned(Json::number_unsigned_t v) { return put(v) != nullptr; }
  bool number_float(Json::number_float_t v, const Json::string_t&) { return put(v) != nullptr; }
  bool string(Json::string_t& v) { return put(std::move(v)) != nullptr; }
  bool binary(Json::binary_t& v) { return put(Json::binary(std::move(v))) != nullptr; }
  bool start_object(std::size_t) {
    open_.push_back(put(Json::value_t::object));
    return true;
  }
  bool key(Json::string_t& k) {
    auto& members = open_.back()->get_ref<Json::object_t&>();
    members.emplace_back(std::move(k), nullptr);   // ordered_map is a vector of (key, value)
    member_ = &members.back().second;
    return true;
  }
  bool end_object() {
    open_.pop_back();
    return true;
  }
  bool start_array(std::size_t) {
    open_.push_back(put(Json::value_t::array));
    return true;
  }
  bool end_array() {
    open_.pop_back();
    return true;
  }
  template <class Exception>
  bool parse_error(std::size_t, const std::string&, const Exception& e) {
    throw e;
  }

 private:
  // The value at the place the parser is at: the root, the next element of the open array, or
  // the member whose key came last.
  template <class V>
  Json* put(V&& v) {
    if (open_.empty()) {
      root_ = Json(std::forward<V>(v));
      return &root_;
    }
    if (open_.back()->is_array()) {
      auto& elements = open_.back()->get_ref<Json::array_t&>();
      elements.emplace_back(std::forward<V>(v));
      return &elements.back();
    }
    *member_ = Json(std::forward<V>(v));
    return member_;
  }
  Json& root_;
  std::vector<Json*> open_;   // the arrays and objects being filled, outermost first
  Json* member_ = nullptr;
};
}  // namespace detail

// Nesting past kMaxJsonDepth and repeated keys are InputErrors too (json_structure.hpp).
inline Json parse_json_text(const std::string& text, const std::string& file, int64_t first_line = 1) {
  // nlohmann stops at a NUL as at the end of the text ("unexpected end of input" at 1:1 for a file
  // that starts with one): name the byte instead.
  if (const std::size_t nul = text.find('\0'); nul != std::string::npos)
    throw InputError(text_position(text, nul + 1, file, first_line),
                     "not valid JSON: a NUL byte (a binary file?)");
  const JsonStructureFinding structure = scan_json_structure(text);
  if (structure.too_deep_at != 0)
    throw InputError(text_position(text, structure.too_deep_at, file, first_line),
                     "nested deeper than " + std::to_string(kMaxJsonDepth) + " arrays or objects");
  try {
    Json j;
    detail::AppendingDomBuilder builder(j);
    Json::sax_parse(text, &builder);
    if (structure.duplicate_at != 0)
      throw InputError(text_position(text, structure.duplicate_at, file, first_line),
                       "the key \"" + structure.duplicate_key + "\" appears twice in one object (each key once)");
    return j;
  } catch (const nlohmann::json::parse_error& e) {
    // Locate the byte nlohmann stopped at as line:column, and keep its reason.
    std::string reason = e.what();
    if (auto pos = reason.find(": ", reason.find("column")); pos != std::string::npos)
      reason = reason.substr(pos + 2);
    throw InputError(text_position(text, e.byte, file, first_line), "not valid JSON: " + reason);
  } catch (const nlohmann::json::out_of_range& e) {
    // A number no double holds (1e400, a 50-digit integer): nlohmann names the literal, not
    // where it is, so find the literal in the text.
    const std::string what = e.what();
    const std::size_t open = what.find('\''), close = what.rfind('\'');
    const std::string literal = open != std::string::npos && close > open ? what.substr(open + 1, close - open - 1) : "";
    const std::size_t at = literal.empty() ? std::string::npos : text.find(literal);
    throw InputError(at == std::string::npos ? file : text_position(text, at + 1, file, first_line),
                     "a number outside the range of a double" + (literal.empty() ? std::string() : " (" + literal + ")"));
  }
}

// A member of object `j` (at JSON path `path`) whose key is not in `known` is an InputError that
// names it and lists the keys there may be; `j` not an object is the caller's to report.
inline void refuse_unknown_keys(const Json& j, const std::string& path, std::initializer_list<std::string_view> known) {
  if (!j.is_object()) return;
  for (auto it = j.begin(); it != j.end(); ++it) {
    bool found = false;
    for (const std::string_view k : known) found = found || it.key() == k;
    if (found) continue;
    std::string keys;
    for (const std::string_view k : known) {
      keys += keys.empty() ? "" : ", ";
      keys += k;
    }
    throw InputError(join_key(path, it.key()), "unknown key (expected one of: " + keys + ")");
  }
}

// The same error with "file: " in front of its JSON path.
inline InputError in_file(const InputError& e, const std::string& file) {
  return InputError(file + ": " + e.where(), std::string(e.what()).substr(e.where().size() + 2));
}

}  // namespace swarmcheck::json_io
