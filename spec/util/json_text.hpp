#pragma once
// Parsing a JSON document a user wrote: a syntax error becomes an InputError at file:line:col
// with nlohmann's reason, and errors found later at a JSON path get the file name in front.
#include <string>

#include "spec/util/hana_json.hpp"
#include "spec/util/input_error.hpp"

namespace swarmcheck::json_io {

inline Json parse_json_text(const std::string& text, const std::string& file) {
  try {
    return Json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // Locate the byte nlohmann stopped at as line:column, and keep its reason.
    std::size_t line = 1, col = 1;
    for (std::size_t k = 0; k + 1 < e.byte && k < text.size(); ++k) {
      if (text[k] == '\n') {
        ++line;
        col = 1;
      } else {
        ++col;
      }
    }
    std::string reason = e.what();
    if (auto pos = reason.find(": ", reason.find("column")); pos != std::string::npos)
      reason = reason.substr(pos + 2);
    throw InputError(file + ":" + std::to_string(line) + ":" + std::to_string(col),
                     "not valid JSON: " + reason);
  }
}

// The same error with "file: " in front of its JSON path.
inline InputError in_file(const InputError& e, const std::string& file) {
  return InputError(file + ": " + e.where(), std::string(e.what()).substr(e.where().size() + 2));
}

}  // namespace swarmcheck::json_io
