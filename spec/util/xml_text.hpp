#pragma once
// Text inside XML (SVG pictures, FMI model descriptions): the five characters XML reserves,
// escaped.
#include <string>
#include <string_view>

namespace swarmcheck::text {

inline std::string xml_escape(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (const char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace swarmcheck::text
