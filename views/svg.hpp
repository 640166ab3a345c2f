#pragma once
// A small SVG writer: elements as text, numbers with at most 3 decimals (pictures, not data),
// text escaped. Pictures are drawn in pixels with y growing downwards; the world's y grows upwards,
// so callers flip with Frame.
#include <array>
#include <string>
#include <string_view>

namespace swarmcheck::views {

std::string xml_escape(std::string_view s);
std::string num(double v);   // "12.5", "3", "-0.125": shortest of 3-decimal rounding

// World (metres, y up) to picture (pixels, y down).
struct Frame {
  double side_m = 1.0;     // the square world [0, side_m]^2
  double px_per_m = 1.0;
  double margin_px = 0.0;
  double x(double x_m) const { return margin_px + x_m * px_per_m; }
  double y(double y_m) const { return margin_px + (side_m - y_m) * px_per_m; }
};

// Colours, shared by the pictures and the pages (the pages receive them in their data).
using Rgb = std::array<int, 3>;
// The heat map: pheromone t in [0, 1] (after the square-root scale) through these stops.
inline constexpr std::array<Rgb, 7> kHeatStops{{{255, 255, 229}, {254, 227, 145}, {254, 196, 79},
                                                {254, 153, 41}, {236, 112, 20}, {204, 76, 2},
                                                {140, 45, 4}}};
inline constexpr Rgb kObstacle{55, 65, 81};
inline constexpr Rgb kGridLine{200, 200, 200};
inline constexpr Rgb kUnvisitedDot{120, 120, 120};
// Robots cycle through these: colour-blind-safe (Okabe-Ito and ColorBrewer's Dark2), none of them
// near the heat map's yellows and oranges.
inline constexpr std::array<Rgb, 7> kRobotColours{{{0, 114, 178}, {0, 158, 115}, {204, 121, 167},
                                                   {86, 180, 233}, {117, 112, 179},
                                                   {231, 41, 138}, {17, 17, 17}}};

Rgb heat(double t);   // t clamped to [0, 1]
std::string css(Rgb c);   // "#rrggbb"

}  // namespace swarmcheck::views
