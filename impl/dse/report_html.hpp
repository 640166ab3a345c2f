#pragma once
// report.html: one self-contained page (inline CSS and SVG, no scripts, nothing fetched): what
// was swept, the Pareto front named point by point, the scatter, the ranking table and one
// response plot per swept parameter.
#include <cstdint>
#include <string>

#include "impl/dse/design_space.hpp"
#include "impl/dse/results.hpp"
#include "impl/dse/results_io.hpp"

namespace swarmcheck::dse {

std::string report_html(const DesignSpace& space, const DseResults& r, const ResultsContext& ctx);

// "point 8 (ertu_perc=0.009)" for the front's points (the swept parameters that vary), joined
// with "; "; past max_points, "and N more".
std::string front_text(const DesignSpace& space, const DseResults& r, std::size_t max_points = SIZE_MAX);

}  // namespace swarmcheck::dse
