#pragma once
// The report's pictures, as standalone SVG text (no scripts, no external references), drawn from
// the results alone so that their bytes are deterministic.
//
// pareto_svg: each ranked point in the plane of two objectives (the first two Pareto dimensions;
// with one, that objective against the point number), the front highlighted and joined as a
// staircase, points violating an objective constraint hollow.
// response_svg: for one swept parameter, one panel per objective: the objective's mean against
// the parameter's value (text values evenly spaced), with 95 % intervals as bars.
#include <cstddef>
#include <string>

#include "impl/dse/design_space.hpp"
#include "impl/dse/results.hpp"

namespace swarmcheck::dse {

std::string pareto_svg(const DesignSpace& space, const DseResults& r);
std::string response_svg(const DesignSpace& space, const DseResults& r, std::size_t parameter);

// Text for XML content and attributes.
std::string xml_escape(const std::string& s);

}  // namespace swarmcheck::dse
