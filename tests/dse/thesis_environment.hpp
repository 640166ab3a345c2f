#pragma once
// The thesis's preliminary (abstract) Environment FMU, transliterated from its listings
// (setEnvironment, findNeighbourhood, findBestNeighbour, move, updatePheromone,
// updateContribution, tick; thesis section 4.2) with the deterministic choice the foundation
// issue fixed for the `thesis` rule set: the best starts at pow(1000, phi) * pow(eta, lambda) /
// sum and a cell becomes best when its probability is <= the best (the last minimum; none: the
// last candidate); a blocked best falls back to the first free cell of the scan (a copy: the
// real cell is not marked); the deposit goes around the chosen best; visited is recounted from
// the flags. eP = visited / free * 100 and sTime = steps * step_size, frozen at eP = 100.
//
// It shares no code with swarmcheck (no spec/, model/ or impl/ include): an independent oracle
// for "each DSE point gives the eP and sTime the thesis's own code gives".
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace swarmcheck::testing::thesis {

struct Setup {
  int map_size = 10;
  std::vector<std::pair<double, double>> robots;   // metres, cell side 1
  std::vector<std::pair<int, int>> obstacles;      // 0-based cells
  int s_range = 1;
  double a1 = 0.5, a2 = 0.5, epsilon = 0.5, max_ph = 2, ertu_perc = 0.1, eta = 0.9, phi = 1, lambda = 1, step_size = 0.1;
  int steps = 199;
};

struct Outputs {
  double eP = 0, sTime = 0;
  int steps = 0;
};

class Environment {
 public:
  explicit Environment(const Setup& s) : s_(s), n_(s.map_size), map_(static_cast<std::size_t>(n_ * n_)) {
    for (const auto& [x, y] : s_.robots) {   // setEnvironment: robots first, then obstacles
      const int i = static_cast<int>(std::floor(x)), j = static_cast<int>(std::floor(y));
      update_contribution(i, j);
      at(i, j).robot = true;
      at(i, j).visited = true;
      pos_.push_back({i, j});
    }
    free_cells_ = n_ * n_;
    for (const auto& [i, j] : s_.obstacles) {
      at(i, j).obstacle = true;
      --free_cells_;
    }
    visited_ = static_cast<int>(pos_.size());
    eP_ = static_cast<double>(visited_) / free_cells_ * 100;
  }

  Outputs run() {
    int step = 0;
    for (; step < s_.steps && eP_ < 100; ++step) tick(step + 1);
    return Outputs{eP_, sTime_, step};
  }

 private:
  struct Cell {
    double pheromone = 0;
    bool visited = false, robot = false, obstacle = false;
  };
  Cell& at(int i, int j) { return map_[static_cast<std::size_t>(i * n_ + j)]; }
  bool in_map(int i, int j) const { return i >= 0 && j >= 0 && i < n_ && j < n_; }

  void update_contribution(int ci, int cj) {
    for (int i = ci - s_.s_range; i <= ci + s_.s_range; ++i)
      for (int j = cj - s_.s_range; j <= cj + s_.s_range; ++j) {
        if (!in_map(i, j)) continue;
        const double di = ci - i, dj = cj - j;
        const double eD = std::sqrt(di * di + dj * dj);
        at(i, j).pheromone += s_.max_ph * std::exp(-eD / s_.a1) + s_.epsilon / s_.a2;
      }
  }

  // findNeighbourhood + findBestNeighbour + move for robot r; returns the best (deposit centre).
  std::pair<int, int> plan(std::size_t r) {
    const auto [ci, cj] = pos_[r];
    double sum = 0;
    std::vector<std::pair<int, int>> candidates, free;
    for (int i = ci - s_.s_range; i <= ci + s_.s_range; ++i)
      for (int j = cj - s_.s_range; j <= cj + s_.s_range; ++j) {
        if (!in_map(i, j) || (i == ci && j == cj)) continue;
        sum += std::pow(at(i, j).pheromone, s_.phi) * std::pow(s_.eta, s_.lambda);
        candidates.push_back({i, j});
        if (!at(i, j).robot && !at(i, j).obstacle) free.push_back({i, j});
      }
    if (candidates.empty()) return pos_[r];
    double best_p = std::pow(1000.0, s_.phi) * std::pow(s_.eta, s_.lambda) / sum;
    std::pair<int, int> best = candidates.back();
    bool found = false;
    for (const auto& [i, j] : candidates) {
      const double p = std::pow(at(i, j).pheromone, s_.phi) * std::pow(s_.eta, s_.lambda) / sum;
      if (p <= best_p) {
        best_p = p;
        best = {i, j};
        found = true;
      }
    }
    if (!found) best = candidates.back();
    Cell& b = at(best.first, best.second);
    if ((b.robot || b.obstacle) && !free.empty()) {
      at(ci, cj).robot = false;   // the copy of free[0] is marked, not the cell itself
      pos_[r] = free.front();
    } else if (b.robot || b.obstacle) {
      b.visited = true;           // stays; the blocked best is "visited"
    } else {
      at(ci, cj).robot = false;
      b.robot = true;
      b.visited = true;
      pos_[r] = best;
    }
    return best;
  }

  void tick(int step_count) {
    std::vector<std::pair<int, int>> bests;
    for (std::size_t r = 0; r < pos_.size(); ++r) bests.push_back(plan(r));
    visited_ = 0;
    for (const Cell& c : map_) visited_ += c.visited ? 1 : 0;
    const double c = s_.ertu_perc * s_.step_size;
    for (Cell& cell : map_) {
      cell.pheromone = cell.pheromone - c * cell.pheromone;
      if (cell.pheromone < 0) cell.pheromone = 0;
    }
    for (const auto& [i, j] : bests) update_contribution(i, j);
    eP_ = static_cast<double>(visited_) / free_cells_ * 100;
    sTime_ = step_count * s_.step_size;
  }

  Setup s_;
  int n_;
  std::vector<Cell> map_;
  std::vector<std::pair<int, int>> pos_;
  int free_cells_ = 0, visited_ = 0;
  double eP_ = 0, sTime_ = 0;
};

}  // namespace swarmcheck::testing::thesis
