#include "impl/dse/report_html.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <numeric>

#include "impl/dse/format.hpp"
#include "impl/dse/report_svg.hpp"

namespace swarmcheck::dse {
namespace {

constexpr const char* kStyle = R"(body{font-family:sans-serif;margin:2em;color:#222;max-width:1100px}
h1{font-size:1.4em}h2{font-size:1.15em;margin-top:1.6em}
table{border-collapse:collapse;font-size:0.85em}th,td{border:1px solid #ccc;padding:2px 6px;text-align:right}
th{background:#f0f0f0}td.s{text-align:left}tr.front td{background:#e8f0fc;font-weight:bold}
.note{color:#555;font-size:0.9em}figure{margin:1em 0})";

std::string objective_cell(const PointResult& p, std::size_t k) {
  if (p.objectives.empty() || !p.objectives[k].present) return "";
  const ObjectiveValue& v = p.objectives[k];
  std::string s = number_text(v.mean);
  if (v.ci95) s += " &plusmn; " + number_text(*v.ci95);
  return s;
}

std::string table_header(const DseConfig& c, bool genetic) {
  std::string h = "<tr><th>point</th>";
  if (genetic) h += "<th>generation</th>";
  for (const SweptParameter& p : c.parameters) h += "<th title=\"" + xml_escape(p.name) + "\">" + xml_escape(plain_name(p.name)) + "</th>";
  for (std::size_t k = 0; k < c.objectives.size(); ++k) {
    const std::string dir = objective_direction(c, k);
    h += "<th>" + xml_escape(c.objectives[k].name) + (dir.empty() ? "" : " (" + dir + ")") + "</th>";
  }
  return h + "<th>runs</th><th>status</th><th>rank</th></tr>\n";
}

std::string table_row(const DesignSpace& space, const DseResults& r, std::size_t i, bool genetic) {
  const PointResult& p = r.points[i];
  std::string row = std::string(p.front ? "<tr class=\"front\">" : "<tr>") + "<td>" + std::to_string(i + 1) + "</td>";
  if (genetic) row += "<td>" + std::to_string(p.generation) + "</td>";
  for (std::size_t k = 0; k < space.config().parameters.size(); ++k)
    row += "<td>" + xml_escape(parameter_value_text(space, p.genome, k)) + "</td>";
  for (std::size_t k = 0; k < space.config().objectives.size(); ++k) row += "<td>" + objective_cell(p, k) + "</td>";
  return row + "<td>" + std::to_string(p.replicates) + "</td><td class=\"s\">" + xml_escape(p.status) + "</td><td>" +
         (p.rank > 0 ? std::to_string(p.rank) : "") + "</td></tr>\n";
}

std::string summary(const DesignSpace& space, const DseResults& r, const ResultsContext& ctx) {
  const DseConfig& c = space.config();
  std::size_t ran = 0, feasible = 0;
  for (const PointResult& p : r.points) {
    ran += p.replicates > 0;
    feasible += p.feasible;
  }
  std::string s = "<p>Configuration <code>" + xml_escape(ctx.config_label) + "</code> on <code>" +
                   xml_escape(ctx.scenario_label) + "</code>: ";
  s += c.algorithm == Algorithm::genetic
           ? fmt::format("genetic search, {} generations, {} of {} design points evaluated", r.generations, r.points.size(), space.size())
           : fmt::format("exhaustive sweep of {} design points", r.points.size());
  s += fmt::format("; {} ran, {} feasible (ran, every objective present, constraints hold).</p>\n", ran, feasible);
  s += "<p>Objectives: ";
  for (std::size_t k = 0; k < c.objectives.size(); ++k) {
    const std::string dir = objective_direction(c, k);
    s += (k ? "; " : "") + std::string("<b>") + xml_escape(c.objectives[k].name) + "</b> = " +
         function_name(c.objectives[k].function) + " of " + xml_escape(c.objectives[k].column_id) +
         (dir == "+" ? ", maximised" : dir == "-" ? ", minimised" : "");
  }
  return s + ".</p>\n";
}

}  // namespace

std::string front_text(const DesignSpace& space, const DseResults& r, std::size_t max_points) {
  std::string s;
  for (std::size_t k = 0; k < r.front.size() && k < max_points; ++k)
    s += (s.empty() ? "" : "; ") + fmt::format("point {} ({})", r.front[k] + 1, space.describe(r.points[r.front[k]].genome, true));
  if (r.front.size() > max_points) s += fmt::format("; and {} more", r.front.size() - max_points);
  return s.empty() ? "none" : s;
}

std::string report_html(const DesignSpace& space, const DseResults& r, const ResultsContext& ctx) {
  const DseConfig& c = space.config();
  const bool genetic = c.algorithm == Algorithm::genetic;
  std::string h = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>swarmcheck DSE: " +
                  xml_escape(ctx.config_label) + "</title>\n<style>" + kStyle + "</style></head><body>\n";
  h += "<h1>Design-space exploration: " + xml_escape(ctx.config_label) + "</h1>\n" + summary(space, r, ctx);
  h += fmt::format("<h2>Pareto front ({} point{})</h2>\n", r.front.size(), r.front.size() == 1 ? "" : "s");
  if (c.pareto.empty()) h += "<p class=\"note\">The configuration ranks nothing (ranking.pareto is empty).</p>\n";
  h += "<p id=\"front\">" + xml_escape(front_text(space, r)) + "</p>\n";
  if (!r.front.empty()) {
    h += "<table>\n" + table_header(c, genetic);
    for (const std::size_t i : r.front) h += table_row(space, r, i, genetic);
    h += "</table>\n";
  }
  h += "<figure>\n" + pareto_svg(space, r) + "</figure>\n";
  h += "<h2>Ranking</h2>\n<p class=\"note\">Every design point by Pareto rank (1 is the front), then point number; "
       "unranked points last. Means over replicates &plusmn; the 95 % interval's half-width.</p>\n<table>\n" +
       table_header(c, genetic);
  std::vector<std::size_t> order(r.points.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const auto key = [&](std::size_t i) { return r.points[i].rank > 0 ? r.points[i].rank : INT32_MAX; };
    return key(a) < key(b);
  });
  for (const std::size_t i : order) h += table_row(space, r, i, genetic);
  h += "</table>\n<h2>Response plots</h2>\n";
  for (std::size_t p = 0; p < c.parameters.size(); ++p) h += "<figure>\n" + response_svg(space, r, p) + "</figure>\n";
  return h + "<p class=\"note\">Written by swarmcheck dse.</p>\n</body></html>\n";
}

}  // namespace swarmcheck::dse
