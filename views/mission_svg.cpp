#include "views/mission_svg.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "spec/util/demand.hpp"
#include "views/svg.hpp"

namespace swarmcheck::views {
namespace {

using swarmcheck::mission::Point;

struct Box {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  void add(const Point& p) {
    x0 = std::min(x0, p[0]);
    y0 = std::min(y0, p[1]);
    x1 = std::max(x1, p[0]);
    y1 = std::max(y1, p[1]);
  }
};

constexpr double kMissionPlotPx = 560.0, kMissionMargin = 20.0, kMissionTop = 56.0;

// A world's walls: the grid's border, and each row's runs of occupied cells as one rectangle.
template <class FX, class FY>
std::string walls_svg(const swarmcheck::mission::GridWorld& w, const FX& X, const FY& Y,
                      double scale) {
  const double res = w.resolution_m;
  std::string out = fmt::format(
      "<g class=\"walls\" fill=\"#57534e\">\n<rect class=\"border\" x=\"{}\" y=\"{}\" width=\"{}\" "
      "height=\"{}\" fill=\"none\" stroke=\"#57534e\" stroke-width=\"3\"/>\n",
      num(X(w.origin[0])), num(Y(w.origin[1] + static_cast<double>(w.rows) * res)),
      num(static_cast<double>(w.cols) * res * scale), num(static_cast<double>(w.rows) * res * scale));
  for (std::size_t i = 0; i < w.rows; ++i)
    for (std::size_t j = 0; j < w.cols;) {
      if (!w.occupied[i * w.cols + j]) {
        ++j;
        continue;
      }
      std::size_t end = j;
      while (end < w.cols && w.occupied[i * w.cols + end]) ++end;
      const double x = w.origin[0] + static_cast<double>(j) * res;
      const double top = w.origin[1] + static_cast<double>(w.rows - i) * res;
      out += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/>\n", num(X(x)), num(Y(top)),
                         num(static_cast<double>(end - j) * res * scale), num(res * scale));
      j = end;
    }
  for (const auto& poly : w.polygons) {  // the polygons' outlines over their rasterised cells
    std::string pts;
    for (const auto& q : poly) pts += num(X(q[0])) + "," + num(Y(q[1])) + " ";
    out += fmt::format("<polygon class=\"obstacle\" points=\"{}\" fill=\"#a8a29e\" "
                       "fill-opacity=\"0.5\" stroke=\"#1c1917\" stroke-width=\"1.5\"/>\n", pts);
  }
  for (const auto& poly : w.unknown_polygons) {  // not on the map: dashed, for the sensor to find
    std::string pts;
    for (const auto& q : poly) pts += num(X(q[0])) + "," + num(Y(q[1])) + " ";
    out += fmt::format("<polygon class=\"unknown-obstacle\" points=\"{}\" fill=\"#fca5a5\" "
                       "fill-opacity=\"0.5\" stroke=\"#b91c1c\" stroke-dasharray=\"4 3\"/>\n", pts);
  }
  return out + "</g>\n";
}

}  // namespace

MissionPathRecorder::MissionPathRecorder(std::size_t robots, swarmcheck::mission::RunObserver* next)
    : next_(next), paths_(robots) {}

void MissionPathRecorder::on_event(const swarmcheck::mission::EventRecord& e) {
  if (next_) next_->on_event(e);
}

void MissionPathRecorder::on_interval(const swarmcheck::mission::IntervalRecord& i) {
  if (next_) next_->on_interval(i);
}

void MissionPathRecorder::on_step(const swarmcheck::mission::StepRecord& s) {
  if (next_) next_->on_step(s);
  SWARM_DEMAND(s.positions.size() == paths_.size());
  for (std::size_t k = 0; k < paths_.size(); ++k) {
    auto& path = paths_[k];
    const Point& p = s.positions[k];
    if (path.size() >= 2 && std::hypot(path.back()[0] - p[0], path.back()[1] - p[1]) < 0.02) continue;
    path.push_back(p);
  }
}

std::string mission_svg(const MissionPicture& p) {
  SWARM_DEMAND(p.mission != nullptr);
  const auto& m = *p.mission;
  Box b;
  for (const auto& g : m.regions) { b.add(g.lo); b.add(g.hi); }
  for (const auto& t : m.tasks) b.add(t.at);
  for (const auto& r : m.robots) b.add(r.start);
  for (const auto& path : p.paths) for (const auto& q : path) b.add(q);
  const auto* world = m.world ? &*m.world : nullptr;
  if (world) {  // the whole grid is shown
    b.add(world->origin);
    b.add({world->origin[0] + static_cast<double>(world->cols) * world->resolution_m,
           world->origin[1] + static_cast<double>(world->rows) * world->resolution_m});
  }
  const double span = std::max({b.x1 - b.x0, b.y1 - b.y0, 1e-9});
  const double pad = 0.05 * span;
  const double scale = kMissionPlotPx / (span + 2 * pad);
  const double w = (b.x1 - b.x0 + 2 * pad) * scale, h = (b.y1 - b.y0 + 2 * pad) * scale;
  auto X = [&](double x) { return kMissionMargin + (x - b.x0 + pad) * scale; };
  auto Y = [&](double y) { return kMissionTop + (b.y1 + pad - y) * scale; };
  std::string out = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
      "font-family=\"DejaVu Sans, sans-serif\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
      num(std::max(w + 2 * kMissionMargin, 420.0)), num(h + kMissionTop + kMissionMargin));
  out += fmt::format("<text x=\"{}\" y=\"22\" font-size=\"15\" font-weight=\"bold\">{}</text>\n", num(kMissionMargin), xml_escape(p.title));
  out += fmt::format("<text x=\"{}\" y=\"42\" font-size=\"12\" fill=\"#444\">{}</text>\n", num(kMissionMargin), xml_escape(p.subtitle));
  out += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"#fafafa\" stroke=\"#ccc\"/>\n", num(kMissionMargin), num(kMissionTop), num(w), num(h));
  if (world) out += walls_svg(*world, X, Y, scale);
  out += "<g class=\"regions\" font-size=\"11\">\n";
  for (const auto& g : m.regions) {
    const double rw = (g.hi[0] - g.lo[0]) * scale, rh = (g.hi[1] - g.lo[1]) * scale;
    out += fmt::format("<rect class=\"region\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"#dbeafe\" fill-opacity=\"0.6\" "
                       "stroke=\"#3b82f6\"><title>{}</title></rect>\n",
                       num(X(g.lo[0])), num(Y(g.hi[1])), num(rw), num(rh), xml_escape(g.name));
    if (rw >= 60 && rh >= 30)   // a small region's name would cover the task inside it
      out += fmt::format("<text x=\"{}\" y=\"{}\" fill=\"#1e3a8a\">{}</text>\n", num(X(g.lo[0]) + 3), num(Y(g.hi[1]) + 12), xml_escape(g.name));
  }
  out += "</g>\n<g class=\"tasks\" font-size=\"11\">\n";
  for (const auto& t : m.tasks) {
    const double x = X(t.at[0]), y = Y(t.at[1]);
    out += fmt::format("<path class=\"task\" d=\"M{} {}l6 6l-6 6l-6 -6z\" fill=\"#16a34a\"/><text x=\"{}\" y=\"{}\" fill=\"#14532d\">{}</text>\n",
                       num(x), num(y - 6), num(x + 8), num(y - 6), xml_escape(t.name));
  }
  out += "</g>\n<g class=\"robots\" font-size=\"11\">\n";
  for (std::size_t k = 0; k < m.robots.size(); ++k) {
    const std::string c = css(kRobotColours[k % kRobotColours.size()]);
    const Point start = m.robots[k].start;
    const Point end = k < p.paths.size() && !p.paths[k].empty() ? p.paths[k].back() : start;
    if (k < p.paths.size() && p.paths[k].size() > 1) {
      std::string pts;
      for (const auto& q : p.paths[k]) pts += num(X(q[0])) + "," + num(Y(q[1])) + " ";
      out += fmt::format("<polyline class=\"path\" points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"2.5\" stroke-opacity=\"0.85\"/>\n", pts, c);
    }
    out += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"6\" fill=\"white\" stroke=\"{}\" stroke-width=\"2\"/>\n", num(X(start[0])), num(Y(start[1])), c);
    out += fmt::format("<circle class=\"robot\" cx=\"{}\" cy=\"{}\" r=\"7\" fill=\"{}\" stroke=\"white\" stroke-width=\"1.5\"/>"
                       "<text x=\"{}\" y=\"{}\" font-weight=\"bold\" fill=\"{}\">{}</text>\n",
                       num(X(end[0])), num(Y(end[1])), c, num(X(end[0]) + 9), num(Y(end[1]) + 4), c, xml_escape(m.robots[k].name));
  }
  return out + "</g>\n</svg>\n";
}

}  // namespace swarmcheck::views
