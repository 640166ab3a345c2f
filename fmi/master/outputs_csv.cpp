#include "fmi/master/outputs_csv.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string_view>

namespace swarmcheck::fmi::master {

std::string java_double_text(double v) {
  if (std::isnan(v)) return "NaN";
  if (std::isinf(v)) return v > 0 ? "Infinity" : "-Infinity";
  if (v == 0) return std::signbit(v) ? "-0.0" : "0.0";
  // The shortest decimal that reads back to v: digits and exponent of d.ddd x 10^e.
  char buffer[64];
  const double magnitude = std::fabs(v);
  const auto shortest = std::to_chars(buffer, buffer + sizeof buffer, magnitude, std::chars_format::scientific);
  std::string_view text(buffer, static_cast<std::size_t>(shortest.ptr - buffer));
  std::size_t e_at = text.find('e');
  std::string digits(1, text[0]);
  if (e_at > 1) digits += text.substr(2, e_at - 2);   // after "d."
  // Java picks among the decimals of length 1 or 2 when the shortest has 1 digit: the one closest
  // to v, i.e. v rounded to 2 significant digits (then a trailing 0 drops: "2.0E23" stays 2).
  if (digits.size() == 1) {
    const auto two = std::to_chars(buffer, buffer + sizeof buffer, magnitude, std::chars_format::scientific, 1);
    text = std::string_view(buffer, static_cast<std::size_t>(two.ptr - buffer));
    e_at = text.find('e');
    digits = std::string(1, text[0]) + (text[2] == '0' ? "" : std::string(1, text[2]));
  }
  const int exponent = std::atoi(std::string(text.substr(e_at + 1)).c_str());
  std::string out = v < 0 ? "-" : "";
  if (magnitude >= 1e-3 && magnitude < 1e7) {
    if (exponent >= 0) {
      const auto whole = static_cast<std::size_t>(exponent) + 1;
      std::string integer = digits.substr(0, std::min(whole, digits.size()));
      if (integer.size() < whole) integer.append(whole - integer.size(), '0');
      const std::string fraction = digits.size() > whole ? digits.substr(whole) : "0";
      out += integer + "." + fraction;
    } else {
      out += "0." + std::string(static_cast<std::size_t>(-exponent - 1), '0') + digits;
    }
  } else {
    out += digits.substr(0, 1) + "." + (digits.size() > 1 ? digits.substr(1) : "0") + "E" + std::to_string(exponent);
  }
  return out;
}

void OutputsCsv::header(std::ostream& out) const {
  out << "time,step-size";
  for (const std::string& name : master_.recorded_names()) out << ',' << name;
  out << '\n';
}

void OutputsCsv::row(std::ostream& out, double time_s, double step_s) const {
  out << java_double_text(time_s) << ',' << java_double_text(step_s);
  for (const Master::Port& p : master_.recorded_ports()) {
    out << ',';
    switch (p.type) {
      case VarType::real: out << java_double_text(master_.value(p)); break;
      case VarType::integer: out << static_cast<long long>(master_.value(p)); break;
      case VarType::boolean: out << (master_.value(p) != 0 ? "true" : "false"); break;
      case VarType::string: {
        out << '"';
        for (const char c : master_.text(p)) {
          if (c == '"') out << '"';
          out << c;
        }
        out << '"';
        break;
      }
    }
  }
  out << '\n';
}

}  // namespace swarmcheck::fmi::master
