#pragma once
// Polygon obstacles of a mission's world (issue 14), as Stage's world files allow: each
// "obstacles" entry {"polygon": [[x, y], ...]} (at least 3 points, finite, non-zero area; the
// closing edge from the last point to the first is implied) is rasterised onto the world's
// occupancy grid by one exact rule:
//
//   cell (i, j) becomes occupied  iff  the closed polygon meets the cell's OPEN square,
//   i.e. some edge of the polygon passes through the open square, or the cell's centre is inside
//   the polygon (even-odd rule).
//
// (If no edge meets the open square, the open square lies wholly inside or wholly outside the
// polygon, so its centre decides.) So a polygon that only touches a cell's border leaves the cell
// free, and a wall thinner than a cell still occupies every cell it passes through: a robot
// checked against the grid can never cross a polygon's edge. An edge meets the open square
// [lo, hi] when the open parameter interval (a, b) of the points of the edge's line strictly
// inside both slabs meets [0, 1]: a < b, a < 1 and b > 0 (Liang-Barsky, strict).
#include <cstddef>
#include <vector>

#include "spec/mission/mission.hpp"

namespace swarmcheck::mission {

// Twice the signed area (shoelace, points in order, the closing edge included).
double polygon_area2(const std::vector<Point>& poly);

// The even-odd rule: a horizontal ray from p to +x crosses an odd number of edges, an edge
// (a, b) counting when (a.y > p.y) != (b.y > p.y) and p.x < a.x + (p.y - a.y)(b.x - a.x)/(b.y - a.y).
bool inside_polygon(const std::vector<Point>& poly, const Point& p);

// The segment [a, b] meets the open square lo < x < hi (both coordinates).
bool segment_meets_open_square(const Point& a, const Point& b, const Point& lo, const Point& hi);

// Per cell of w (row-major): the rule above for this polygon alone.
std::vector<char> polygon_cells(const GridWorld& w, const std::vector<Point>& poly);

}  // namespace swarmcheck::mission
