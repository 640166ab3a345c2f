#include "views/exploration_svg.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "spec/util/demand.hpp"
#include "views/svg.hpp"

namespace swarmcheck::views {
namespace {

using namespace swarmcheck::exploration;

constexpr double kMapPx = 560.0;
constexpr double kMargin = 20.0;
constexpr double kTop = 72.0;
constexpr double kLegendPx = 90.0;

// One drawn block of cells (a single cell on maps up to kPictureCellsMax).
struct Block {
  double pheromone = 0.0;
  bool obstacle = true;     // every cell of the block is an obstacle
  bool unvisited = false;   // some free cell of the block is unvisited
};

std::vector<Block> blocks(const ExplorationPicture& p, int32_t b, int32_t nb) {
  const int32_t n = p.scenario.map_size;
  std::vector<bool> obstacle(static_cast<std::size_t>(n) * static_cast<std::size_t>(n), false);
  for (const CellIndex& c : p.scenario.obstacles)
    obstacle[static_cast<std::size_t>(c[0]) * static_cast<std::size_t>(n) + static_cast<std::size_t>(c[1])] = true;
  std::vector<Block> out(static_cast<std::size_t>(nb) * static_cast<std::size_t>(nb));
  for (int32_t i = 0; i < n; ++i)
    for (int32_t j = 0; j < n; ++j) {
      const std::size_t k = static_cast<std::size_t>(i) * static_cast<std::size_t>(n) + static_cast<std::size_t>(j);
      Block& blk = out[static_cast<std::size_t>(i / b) * static_cast<std::size_t>(nb) + static_cast<std::size_t>(j / b)];
      blk.pheromone = std::max(blk.pheromone, p.field.pheromone[k]);
      if (!obstacle[k]) {
        blk.obstacle = false;
        if (!p.field.visited[k]) blk.unvisited = true;
      }
    }
  return out;
}

// Cells, one rectangle per run of equal colour along a column (i fixed, j increasing: y up).
std::string cells_svg(const ExplorationPicture& p, const Frame& f) {
  const int32_t n = p.scenario.map_size;
  const int32_t b = (n + kPictureCellsMax - 1) / kPictureCellsMax;
  const int32_t nb = (n + b - 1) / b;
  const std::vector<Block> bl = blocks(p, b, nb);
  double vmax = 0.0;
  for (const Block& x : bl) vmax = std::max(vmax, x.pheromone);
  const double block_m = b * p.scenario.cell_size;
  auto colour = [&](const Block& x) {
    return x.obstacle ? css(kObstacle) : css(heat(vmax > 0 ? std::sqrt(x.pheromone / vmax) : 0.0));
  };
  std::string out = "<g class=\"cells\" shape-rendering=\"crispEdges\">\n";
  for (int32_t bi = 0; bi < nb; ++bi) {
    int32_t start = 0;
    for (int32_t bj = 1; bj <= nb; ++bj) {
      const auto at = [&](int32_t j) { return bl[static_cast<std::size_t>(bi) * static_cast<std::size_t>(nb) + static_cast<std::size_t>(j)]; };
      if (bj < nb && colour(at(bj)) == colour(at(start))) continue;
      const double x0 = f.x(bi * block_m), x1 = f.x(std::min<double>((bi + 1) * block_m, f.side_m));
      const double y1 = f.y(start * block_m), y0 = f.y(std::min<double>(bj * block_m, f.side_m));
      out += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{}\"/>\n", num(x0),
                         num(y0), num(x1 - x0), num(y1 - y0), colour(at(start)));
      start = bj;
    }
  }
  out += "</g>\n<g class=\"unvisited\" fill=\"" + css(kUnvisitedDot) + "\">\n";
  const double r = std::max(1.0, 0.12 * block_m * f.px_per_m);
  for (int32_t bi = 0; bi < nb; ++bi)
    for (int32_t bj = 0; bj < nb; ++bj)
      if (bl[static_cast<std::size_t>(bi) * static_cast<std::size_t>(nb) + static_cast<std::size_t>(bj)].unvisited)
        out += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"{}\"/>\n", num(f.x((bi + 0.5) * block_m)),
                           num(f.y((bj + 0.5) * block_m)), num(r));
  out += "</g>\n";
  if (nb <= 40) {
    out += "<g class=\"grid\" stroke=\"" + css(kGridLine) + "\" stroke-width=\"0.5\">\n";
    for (int32_t k = 0; k <= nb; ++k) {
      const double m = std::min<double>(k * block_m, f.side_m);
      out += fmt::format("<line x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\"/><line x1=\"{1}\" y1=\"{3}\" x2=\"{2}\" y2=\"{3}\"/>\n",
                         num(f.x(m)), num(f.y(f.side_m)), num(f.y(0)), num(f.y(m)));
    }
    out += "</g>\n";
  }
  return out;
}

std::string robots_svg(const ExplorationPicture& p, const Frame& f) {
  const double r = std::clamp(0.3 * p.scenario.cell_size * f.px_per_m, 2.5, 9.0);
  const bool cosim = p.scenario.mode == Mode::cosim;
  std::string out = "<g class=\"robots\">\n";
  for (std::size_t k = 0; k < p.paths.size(); ++k) {
    const std::string c = css(kRobotColours[k % kRobotColours.size()]);
    const auto& path = p.paths[k];
    if (path.empty()) continue;
    std::string pts;
    for (const Point_m& q : path) pts += num(f.x(q[0])) + "," + num(f.y(q[1])) + " ";
    out += fmt::format("<polyline class=\"path\" points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"1.4\" "
                       "stroke-opacity=\"0.55\" stroke-linejoin=\"round\"/>\n", pts, c);
    out += fmt::format("<circle class=\"start\" cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"white\" stroke=\"{}\" stroke-width=\"2\"/>\n",
                       num(f.x(path.front()[0])), num(f.y(path.front()[1])), num(r * 0.8), c);
    if (k >= p.poses.size()) continue;
    const BodyState& b = p.poses[k];
    out += fmt::format("<circle class=\"robot\" data-robot=\"{}\" cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{}\" stroke=\"#111\" stroke-width=\"1.5\"/>\n",
                       k, num(f.x(b.x_m)), num(f.y(b.y_m)), num(r), c);
    if (cosim)   // forward is (-sin theta, cos theta)
      out += fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"white\" stroke-width=\"2\"/>\n",
                         num(f.x(b.x_m)), num(f.y(b.y_m)), num(f.x(b.x_m) - std::sin(b.theta_rad) * r),
                         num(f.y(b.y_m) - std::cos(b.theta_rad) * r));
  }
  return out + "</g>\n";
}

std::string legend_svg(double x, double y, double h) {
  std::string out = "<g class=\"legend\" font-size=\"11\">\n<defs><linearGradient id=\"heat\" x1=\"0\" y1=\"1\" x2=\"0\" y2=\"0\">";
  for (std::size_t k = 0; k < kHeatStops.size(); ++k)
    out += fmt::format("<stop offset=\"{}\" stop-color=\"{}\"/>", num(static_cast<double>(k) / (kHeatStops.size() - 1)),
                       css(kHeatStops[k]));
  out += "</linearGradient></defs>\n";
  out += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"14\" height=\"{}\" fill=\"url(#heat)\" stroke=\"#999\"/>\n", num(x), num(y), num(h));
  out += fmt::format("<text x=\"{}\" y=\"{}\">max</text><text x=\"{}\" y=\"{}\">0</text>\n", num(x + 18), num(y + 9), num(x + 18), num(y + h));
  out += fmt::format("<text x=\"{}\" y=\"{}\">pheromone</text><text x=\"{}\" y=\"{}\">(√ scale)</text>\n",
                     num(x - 4), num(y + h + 18), num(x - 4), num(y + h + 32));
  out += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"14\" height=\"14\" fill=\"{}\"/><text x=\"{}\" y=\"{}\">obstacle</text>\n",
                     num(x), num(y + h + 46), css(kObstacle), num(x + 18), num(y + h + 57));
  out += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"3\" fill=\"{}\"/><text x=\"{}\" y=\"{}\">unvisited</text>\n",
                     num(x + 7), num(y + h + 74), css(kUnvisitedDot), num(x + 18), num(y + h + 78));
  return out + "</g>\n";
}

}  // namespace

std::string exploration_svg(const ExplorationPicture& p) {
  const int32_t n = p.scenario.map_size;
  SWARM_DEMAND(n >= 1);
  SWARM_DEMAND(p.field.pheromone.size() == static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
  Frame f;
  f.side_m = n * p.scenario.cell_size;
  f.px_per_m = kMapPx / f.side_m;
  f.margin_px = kMargin;
  const double width = kMargin + kMapPx + kMargin + kLegendPx;
  const double height = kTop + kMapPx + kMargin;
  std::string out = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
      "font-family=\"DejaVu Sans, sans-serif\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
      num(width), num(height));
  out += fmt::format("<text x=\"{}\" y=\"22\" font-size=\"15\" font-weight=\"bold\">{}</text>\n", num(kMargin), xml_escape(p.title));
  // The subtitle's lines are separated by '\n'.
  double y = 40;
  for (std::size_t at = 0; at <= p.subtitle.size(); y += 16) {
    std::size_t end = p.subtitle.find('\n', at);
    if (end == std::string::npos) end = p.subtitle.size();
    out += fmt::format("<text x=\"{}\" y=\"{}\" font-size=\"12\" fill=\"#444\">{}</text>\n", num(kMargin), num(y),
                       xml_escape(p.subtitle.substr(at, end - at)));
    at = end + 1;
  }
  out += fmt::format("<g transform=\"translate(0 {})\">\n", num(kTop - kMargin));
  out += cells_svg(p, f);
  out += fmt::format("<rect x=\"{0}\" y=\"{0}\" width=\"{1}\" height=\"{1}\" fill=\"none\" stroke=\"#333\"/>\n", num(kMargin), num(kMapPx));
  out += robots_svg(p, f);
  out += legend_svg(kMargin + kMapPx + kMargin + 8, kMargin, 200);
  return out + "</g>\n</svg>\n";
}

}  // namespace swarmcheck::views
