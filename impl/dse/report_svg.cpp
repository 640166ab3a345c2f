#include "impl/dse/report_svg.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "impl/dse/format.hpp"
#include "impl/dse/results_io.hpp"

namespace swarmcheck::dse {
namespace {

constexpr const char* kFront = "#1f5fbf";
constexpr const char* kOther = "#8c8c8c";
constexpr const char* kViolating = "#c0392b";

// A linear axis from data values [lo, hi] onto pixels [p0, p1], padded by 5 %, or evenly spaced
// categories when `labels` is not empty.
struct Axis {
  double lo = 0, hi = 1, p0 = 0, p1 = 1;
  std::vector<std::string> labels;
  double at(double v) const { return p0 + (v - lo) / (hi - lo) * (p1 - p0); }
};

Axis numeric_axis(const std::vector<double>& values, double p0, double p1) {
  Axis a;
  a.p0 = p0;
  a.p1 = p1;
  if (values.empty()) return a;
  const auto [mn, mx] = std::minmax_element(values.begin(), values.end());
  double lo = *mn, hi = *mx;
  if (!(hi > lo)) {
    const double pad = lo == 0 ? 1 : std::fabs(lo) * 0.1;
    lo -= pad;
    hi += pad;
  }
  const double pad = (hi - lo) * 0.05;
  a.lo = lo - pad;
  a.hi = hi + pad;
  return a;
}

Axis category_axis(std::vector<std::string> labels, double p0, double p1) {
  Axis a;
  a.labels = std::move(labels);
  a.lo = -0.5;
  a.hi = static_cast<double>(a.labels.size()) - 0.5;
  a.p0 = p0;
  a.p1 = p1;
  return a;
}

// About five round tick values inside [lo, hi], and the decimals that print them exactly enough.
std::pair<std::vector<double>, int> ticks(double lo, double hi) {
  const double raw = (hi - lo) / 5;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double r = raw / mag;
  const double step = (r < 1.5 ? 1 : r < 3.5 ? 2 : r < 7.5 ? 5 : 10) * mag;
  std::vector<double> out;
  for (double t = std::ceil(lo / step) * step; t <= hi + step * 1e-9 && out.size() < 20; t += step)
    out.push_back(std::fabs(t) < step * 1e-9 ? 0.0 : t);
  const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
  return {out, decimals};
}

std::string px(double v) { return fmt::format("{:.2f}", v); }

// The frame of one plot: axes, ticks, grid and labels. x runs p0..p1 left to right, y bottom to top.
std::string frame(const Axis& x, const Axis& y, const std::string& x_label, const std::string& y_label) {
  std::string s;
  const double left = x.p0, right = x.p1, bottom = y.p0, top = y.p1;
  s += fmt::format(R"(<rect x="{}" y="{}" width="{}" height="{}" fill="#ffffff" stroke="#444" stroke-width="1"/>)" "\n",
                   px(left), px(top), px(right - left), px(bottom - top));
  if (x.labels.empty()) {
    const auto [tx, dx] = ticks(x.lo, x.hi);
    for (const double t : tx)
      s += fmt::format(R"(<line x1="{0}" y1="{1}" x2="{0}" y2="{2}" stroke="#e4e4e4"/><text x="{0}" y="{3}" text-anchor="middle">{4}</text>)" "\n",
                       px(x.at(t)), px(top), px(bottom), px(bottom + 14), fmt::format("{:.{}f}", t, dx));
  } else {
    for (std::size_t k = 0; k < x.labels.size(); ++k)
      s += fmt::format(R"(<text x="{}" y="{}" text-anchor="middle">{}</text>)" "\n", px(x.at(static_cast<double>(k))),
                       px(bottom + 14), xml_escape(x.labels[k]));
  }
  const auto [ty, dy] = ticks(y.lo, y.hi);
  for (const double t : ty)
    s += fmt::format(R"(<line x1="{0}" y1="{1}" x2="{2}" y2="{1}" stroke="#e4e4e4"/><text x="{3}" y="{4}" text-anchor="end">{5}</text>)" "\n",
                     px(left), px(y.at(t)), px(right), px(left - 4), px(y.at(t) + 4), fmt::format("{:.{}f}", t, dy));
  s += fmt::format(R"(<text x="{}" y="{}" text-anchor="middle" font-weight="bold">{}</text>)" "\n", px((left + right) / 2),
                   px(bottom + 32), xml_escape(x_label));
  s += fmt::format(R"~(<text transform="translate({},{}) rotate(-90)" text-anchor="middle" font-weight="bold">{}</text>)~" "\n",
                   px(left - 46), px((top + bottom) / 2), xml_escape(y_label));
  return s;
}

std::string svg_open(double width, double height, const std::string& title) {
  return fmt::format(R"(<svg xmlns="http://www.w3.org/2000/svg" width="{0}" height="{1}" viewBox="0 0 {0} {1}" font-family="sans-serif" font-size="11">)" "\n"
                     "<title>{2}</title>\n",
                     px(width), px(height), xml_escape(title));
}

std::string axis_name(const DseConfig& c, std::size_t objective) {
  const std::string dir = objective_direction(c, objective);
  return c.objectives[objective].name + (dir == "+" ? " (maximised)" : dir == "-" ? " (minimised)" : "");
}

}  // namespace

std::string xml_escape(const std::string& s) {
  std::string out;
  for (const char c : s) {
    switch (c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string pareto_svg(const DesignSpace& space, const DseResults& r) {
  const DseConfig& c = space.config();
  // The plane: two Pareto dimensions, or one against the point number, or the first objectives.
  std::vector<std::size_t> dims;
  for (const ParetoDimension& d : c.pareto) dims.push_back(d.objective);
  if (dims.empty())
    for (std::size_t k = 0; k < c.objectives.size() && k < 2; ++k) dims.push_back(k);
  const bool by_index = dims.size() < 2;
  const auto xv = [&](std::size_t i) { return by_index ? static_cast<double>(i + 1) : r.points[i].objectives[dims[0]].mean; };
  const auto yv = [&](std::size_t i) { return r.points[i].objectives[by_index ? dims[0] : dims[1]].mean; };
  std::vector<std::size_t> shown;
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const PointResult& p = r.points[i];
    bool ok = !p.objectives.empty();
    for (const std::size_t d : dims) ok = ok && p.objectives[d].present;
    if (ok) shown.push_back(i);
  }
  const double width = 640, height = 440;
  std::vector<double> xs, ys;
  for (const std::size_t i : shown) {
    xs.push_back(xv(i));
    ys.push_back(yv(i));
  }
  const Axis x = numeric_axis(xs, 80, width - 20);
  const Axis y = numeric_axis(ys, height - 60, 30);
  std::string s = svg_open(width, height, "Pareto front");
  s += fmt::format(R"(<text x="{}" y="18" text-anchor="middle" font-size="13" font-weight="bold">Pareto front: {} of {} points</text>)" "\n",
                   px(width / 2), r.front.size(), r.points.size());
  s += frame(x, y, by_index ? "point" : axis_name(c, dims[0]), axis_name(c, by_index ? dims[0] : dims[1]));
  // The front as a staircase in x order.
  std::vector<std::size_t> front = r.front;
  std::sort(front.begin(), front.end(), [&](std::size_t a, std::size_t b) { return std::make_pair(xv(a), a) < std::make_pair(xv(b), b); });
  if (front.size() >= 2) {
    std::string d;
    for (const std::size_t i : front) d += (d.empty() ? "M" : " L") + px(x.at(xv(i))) + "," + px(y.at(yv(i)));
    s += fmt::format(R"(<path d="{}" fill="none" stroke="{}" stroke-width="1.5" stroke-dasharray="4 3"/>)" "\n", d, kFront);
  }
  for (const std::size_t i : shown) {
    const PointResult& p = r.points[i];
    const std::string colour = p.front ? kFront : p.feasible ? kOther : kViolating;
    const std::string fill = p.feasible ? colour : "none";
    s += fmt::format(R"(<circle cx="{}" cy="{}" r="{}" fill="{}" stroke="{}"><title>point {}: {} ({})</title></circle>)" "\n",
                     px(x.at(xv(i))), px(y.at(yv(i))), p.front ? "5" : "3.5", fill, colour, i + 1,
                     xml_escape(space.describe(p.genome, true)), xml_escape(p.status));
    if (p.front)
      s += fmt::format(R"(<text x="{}" y="{}" fill="{}">{}</text>)" "\n", px(x.at(xv(i)) + 7), px(y.at(yv(i)) - 6), kFront, i + 1);
  }
  return s + "</svg>\n";
}

std::string response_svg(const DesignSpace& space, const DseResults& r, std::size_t parameter) {
  const DseConfig& c = space.config();
  const SweptParameter& param = c.parameters[parameter];
  const bool text = knob_info(param.knob).type == ValueType::text;
  const double panel_w = 320, panel_h = 240;
  const std::size_t columns = std::min<std::size_t>(2, c.objectives.size());
  const std::size_t rows = (c.objectives.size() + columns - 1) / columns;
  std::string s = svg_open(panel_w * static_cast<double>(columns), panel_h * static_cast<double>(rows) + 24, "Response to " + param.name);
  s += fmt::format(R"(<text x="8" y="16" font-size="13" font-weight="bold">Response to {}</text>)" "\n", xml_escape(param.name));
  std::vector<double> xvals;
  std::vector<std::string> labels;
  for (const ParameterValue& v : param.values) {
    xvals.push_back(v.number);
    labels.push_back(value_text(v));
  }
  for (std::size_t k = 0; k < c.objectives.size(); ++k) {
    const double ox = panel_w * static_cast<double>(k % columns), oy = 24 + panel_h * static_cast<double>(k / columns);
    std::vector<double> ys;
    std::vector<std::size_t> shown;
    for (std::size_t i = 0; i < r.points.size(); ++i) {
      const PointResult& p = r.points[i];
      if (p.objectives.empty() || !p.objectives[k].present) continue;
      shown.push_back(i);
      ys.push_back(p.objectives[k].mean - p.objectives[k].ci95.value_or(0));
      ys.push_back(p.objectives[k].mean + p.objectives[k].ci95.value_or(0));
    }
    const Axis x = text ? category_axis(labels, ox + 64, ox + panel_w - 14) : numeric_axis(xvals, ox + 64, ox + panel_w - 14);
    const Axis y = numeric_axis(ys, oy + panel_h - 48, oy + 12);
    s += frame(x, y, param.name.size() > 40 ? plain_name(param.name) : param.name, axis_name(c, k));
    for (const std::size_t i : shown) {
      const PointResult& p = r.points[i];
      const std::size_t vi = static_cast<std::size_t>(p.genome[parameter]);
      const double cx = x.at(text ? static_cast<double>(vi) : param.values[vi].number);
      const ObjectiveValue& v = p.objectives[k];
      const std::string colour = p.front ? kFront : p.feasible ? kOther : kViolating;
      if (v.ci95)
        s += fmt::format(R"(<line x1="{0}" y1="{1}" x2="{0}" y2="{2}" stroke="{3}"/>)" "\n", px(cx), px(y.at(v.mean - *v.ci95)),
                         px(y.at(v.mean + *v.ci95)), colour);
      s += fmt::format(R"(<circle cx="{}" cy="{}" r="3.5" fill="{}"><title>point {}: {}</title></circle>)" "\n", px(cx),
                       px(y.at(v.mean)), colour, i + 1, number_text(v.mean));
    }
  }
  return s + "</svg>\n";
}

}  // namespace swarmcheck::dse
