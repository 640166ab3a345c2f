#include "views/svg.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "spec/util/xml_text.hpp"

namespace swarmcheck::views {

std::string xml_escape(std::string_view s) { return text::xml_escape(s); }

std::string num(double v) {
  if (!std::isfinite(v)) return "0";
  const double r = std::round(v * 1000.0) / 1000.0;
  std::string s = fmt::format("{:.3f}", r == 0.0 ? 0.0 : r);
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

Rgb heat(double t) {
  if (!(t > 0.0)) return kHeatStops.front();
  if (t >= 1.0) return kHeatStops.back();
  const double pos = t * static_cast<double>(kHeatStops.size() - 1);
  const auto k = static_cast<std::size_t>(pos);
  const double f = pos - static_cast<double>(k);
  Rgb c{};
  for (int ch = 0; ch < 3; ++ch)
    c[ch] = static_cast<int>(std::lround(kHeatStops[k][ch] + f * (kHeatStops[k + 1][ch] - kHeatStops[k][ch])));
  return c;
}

std::string css(Rgb c) { return fmt::format("#{:02x}{:02x}{:02x}", c[0], c[1], c[2]); }

}  // namespace swarmcheck::views
