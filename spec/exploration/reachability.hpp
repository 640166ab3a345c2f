#pragma once
// Which free cells the robots can ever stand on. A robot moves to a cell of its window (within
// s_range cells, Chebyshev), so a free cell is reachable when a chain of free cells, each within
// s_range of the last, leads to it from some robot's start cell; obstacles block (for s_range 1
// that is the 8-neighbourhood). A free cell no robot can reach keeps a run from completing: the
// CLI says so at the start and reports completion against the reachable cells too.
#include <cstdint>

#include "spec/exploration/types.hpp"

namespace swarmcheck::exploration {

struct Reachability {
  int64_t reachable_free_cells = 0;    // start cells included
  int64_t unreachable_free_cells = 0;  // free_cell_count(s) - reachable_free_cells
};

// Breadth first over the map: O(map_size^2 (2 s_range + 1)^2) time, map_size^2 bits.
Reachability reachability(const Scenario& s);

}  // namespace swarmcheck::exploration
