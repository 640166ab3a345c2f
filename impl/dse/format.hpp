#pragma once
// How the DSE writes values: numbers in their shortest text that reads back as the same double
// (so every output is a function of the results' bits alone), parameter values as written.
#include <charconv>
#include <cmath>
#include <string>

#include "impl/dse/config.hpp"

namespace swarmcheck::dse {

inline std::string number_text(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

inline std::string value_text(const ParameterValue& v) {
  return v.json.is_string() ? v.text : number_text(v.number);
}

// A CSV field (RFC 4180): quoted when it holds a comma, a quote or a line break.
inline std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (const char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace swarmcheck::dse
