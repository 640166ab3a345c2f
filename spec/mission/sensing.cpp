// Unknown obstacles and the range sensor: the rule is in sensing.hpp.
#include "spec/mission/sensing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "spec/mission/world.hpp"
#include "spec/util/demand.hpp"

namespace swarmcheck::mission {

namespace {

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// A uniform in (0, 1] from the top 53 bits.
double unit_of(std::uint64_t x) { return (static_cast<double>(x >> 11) + 1.0) * 0x1.0p-53; }

}  // namespace

GridWorld true_world(const GridWorld& w) {
  GridWorld out = w;
  out.traversable.clear();
  for (std::size_t c = 0; c < w.hidden.size(); ++c) out.occupied[c] = out.occupied[c] || w.hidden[c];
  return out;
}

double sensor_normal(std::uint64_t seed, std::uint64_t step, std::uint64_t robot, std::uint64_t beam) {
  const std::uint64_t a = splitmix64(splitmix64(splitmix64(splitmix64(seed) ^ step) ^ robot) ^ beam);
  const std::uint64_t b = splitmix64(a);
  return std::sqrt(-2.0 * std::log(unit_of(a))) * std::cos(2.0 * std::numbers::pi * unit_of(b));
}

std::vector<std::size_t> scan_cells(const GridWorld& truth, const Point& p, std::uint64_t seed,
                                    std::uint64_t step, std::uint64_t robot) {
  SWARM_DEMAND(truth.sensor_beams > 0);
  SWARM_DEMAND(truth.sensor_range_m >= 0.0);
  const double range = truth.sensor_range_m, dt = truth.resolution_m / 8;
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < truth.sensor_beams; ++k) {
    const double angle = 2.0 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(truth.sensor_beams);
    const double cx = std::cos(angle), cy = std::sin(angle);
    double t = range;
    bool hit = false;
    for (std::size_t n = 1; static_cast<double>(n) * dt <= range; ++n) {
      const double s = static_cast<double>(n) * dt;
      const auto c = cell_of(truth, {p[0] + s * cx, p[1] + s * cy});
      if (!c || truth.occupied[*c]) {
        t = s;
        hit = true;
        break;
      }
    }
    if (!hit) continue;  // no return: the reading is R, exactly
    const double noise = truth.sensor_noise_m == 0.0 ? 0.0 : truth.sensor_noise_m * sensor_normal(seed, step, robot, k);
    const double reading = std::clamp(t + noise, 0.0, range);
    if (reading >= range) continue;
    if (const auto c = cell_of(truth, {p[0] + reading * cx, p[1] + reading * cy})) out.push_back(*c);
  }
  return out;
}

bool add_to_map(std::vector<char>& map, const std::vector<std::size_t>& cells) {
  bool changed = false;
  for (const std::size_t c : cells) {
    SWARM_DEMAND(c < map.size());
    changed = changed || !map[c];
    map[c] = 1;
  }
  return changed;
}

std::vector<char> traversable_on(const GridWorld& w, const std::vector<char>& map, double radius_m) {
  GridWorld mine;
  mine.resolution_m = w.resolution_m;
  mine.origin = w.origin;
  mine.rows = w.rows;
  mine.cols = w.cols;
  mine.occupied = map;
  return traversable_cells(mine, radius_m);
}

}  // namespace swarmcheck::mission
