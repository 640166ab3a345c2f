#pragma once
// The picture of an exploration run (run --svg): the grid with obstacles, the pheromone as a heat
// map (square-root scale, so weak trails stay visible), unvisited free cells dotted, each robot's
// path from its start (hollow circle) to where it stands (filled, with its heading in cosim).
// Maps above 128 x 128 cells are drawn in blocks (the block's largest pheromone; dotted when any
// free cell in it is unvisited), so a picture stays small whatever the map.
#include <string>
#include <vector>

#include "spec/exploration/trace_field.hpp"
#include "spec/exploration/types.hpp"

namespace swarmcheck::views {

struct ExplorationPicture {
  swarmcheck::exploration::Scenario scenario;
  swarmcheck::exploration::FieldSnapshot field;                // the grid at the end
  std::vector<std::vector<swarmcheck::exploration::Point_m>> paths;  // per robot, metres
  std::vector<swarmcheck::exploration::BodyState> poses;         // per robot, at the end
  std::string title;
  std::string subtitle;
};

inline constexpr int kPictureCellsMax = 128;   // cells per side drawn one by one

std::string exploration_svg(const ExplorationPicture& p);

}  // namespace swarmcheck::views
