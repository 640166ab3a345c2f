#include "python/src/simulation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "spec/util/budget.hpp"

#include "views/exploration_svg.hpp"

namespace ex = swarmcheck::exploration;

namespace swarmcheck::python {

void require_memory(const PyScenario& s, std::uint64_t limit_bytes) {
  const ex::Scenario& v = s.valid.get();
  // As `run`: the process (15 MiB, the CLI's kProcessBytes), and the larger of the map's cells and
  // the reachability check's bit per cell and queue.
  const double cells = static_cast<double>(v.map_size) * v.map_size;
  const double estimate = 15.0 * (1 << 20) + std::max(static_cast<double>(ex::Exploration::estimated_bytes(v)),
                                                       cells / 8 + cells * 8);
  require_within(s.where, "a " + std::to_string(v.map_size) + " x " + std::to_string(v.map_size) + " map with " +
                              std::to_string(v.robots.size()) + " robots",
                 estimate, limit_bytes, "memory_limit");
}

PySimulation::PySimulation(PyScenario s, int32_t threads, bool paths)
    : scenario_(std::move(s)),
      run_(scenario_.valid, ex::ExplorationOptions{.threads = threads}),
      record_paths_(paths) {
  const ex::Scenario& v = scenario_.valid.get();
  // As `run --svg` (views/run_recorder.cpp): on big maps the paths are sampled.
  path_every_ = std::max<int64_t>(1, int64_t{v.map_size} * v.map_size / 4096);
  if (record_paths_) {
    paths_.resize(v.robots.size());
    after_step();
  }
}

void PySimulation::after_step() {
  if (!record_paths_ || !(run_.steps() % path_every_ == 0 || run_.done())) return;
  const double cell = scenario_.valid.get().cell_size;
  const auto bodies = run_.bodies();
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    const ex::BodyState& b = bodies[k];
    auto& path = paths_[k];
    // A point when the robot has moved a tenth of a cell (cosim paths are dense).
    if (!path.empty() && std::hypot(path.back()[0] - b.x_m, path.back()[1] - b.y_m) < 0.1 * cell) continue;
    path.push_back({b.x_m, b.y_m});
  }
}

void PySimulation::step(int64_t n) {
  if (n == 1) {   // the common loop `while not sim.done: sim.step()`: no GIL hand-over
    if (!run_.done()) {
      run_.step();
      after_step();
    }
    return;
  }
  without_gil([&](SignalPoll& poll) {
    for (int64_t k = 0; k < n && !run_.done(); ++k) {
      run_.step();
      after_step();
      poll();
    }
    return 0;
  });
}

const ex::Reachability& PySimulation::reach() {
  if (!reach_) reach_ = ex::reachability(scenario_.valid.get());
  return *reach_;
}

json_io::Json PySimulation::run(int64_t stall_window) {
  const ex::Reachability r = reach();
  return without_gil([&](SignalPoll& poll) {
    const ex::RunEnd end = ex::run_to_end(run_, r, stall_window, [&](const ex::Exploration&, bool) {
      after_step();
      poll();
    });
    return ex::run_report(run_, end, "impl");
  });
}

const std::vector<double>& PySimulation::current_field() {
  const int32_t n = scenario_.valid.get().map_size;
  if (field_.empty()) field_.resize(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
  if (field_step_ != run_.steps()) {
    for (int32_t i = 0; i < n; ++i)
      for (int32_t j = 0; j < n; ++j)
        field_[static_cast<std::size_t>(i) * n + static_cast<std::size_t>(j)] = run_.cell({i, j}).pheromone;
    field_step_ = run_.steps();
  }
  return field_;
}

std::vector<uint8_t> PySimulation::visited_mask() const {
  const int32_t n = scenario_.valid.get().map_size;
  std::vector<uint8_t> out(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
  for (int32_t i = 0; i < n; ++i)
    for (int32_t j = 0; j < n; ++j) out[static_cast<std::size_t>(i) * n + static_cast<std::size_t>(j)] = run_.cell({i, j}).visited;
  return out;
}

// The picture `swarmcheck run --svg` draws (views/exploration_svg.hpp), at the current step.
std::string PySimulation::svg() const {
  const ex::Scenario& s = scenario_.valid.get();
  views::ExplorationPicture p;
  p.scenario = s;
  p.field.step = run_.steps();
  p.field.map_size = s.map_size;
  const std::size_t n = static_cast<std::size_t>(s.map_size);
  p.field.pheromone.resize(n * n);
  p.field.visited.resize(n * n);
  for (int32_t i = 0; i < s.map_size; ++i)
    for (int32_t j = 0; j < s.map_size; ++j) {
      const ex::Cell c = run_.cell({i, j});
      p.field.pheromone[static_cast<std::size_t>(i) * n + static_cast<std::size_t>(j)] = c.pheromone;
      p.field.visited[static_cast<std::size_t>(i) * n + static_cast<std::size_t>(j)] = c.visited;
    }
  p.paths = paths_;
  p.paths.resize(s.robots.size());
  const auto bodies = run_.bodies();
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    p.poses.push_back(bodies[k]);
    p.paths[k].push_back({bodies[k].x_m, bodies[k].y_m});
  }
  p.title = scenario_.where;
  p.subtitle = fmt::format("map {}x{}, {} robots, {} obstacles, rule {}, mode {}, seed {}\n", s.map_size, s.map_size,
                           s.robots.size(), s.obstacles.size(), json_io::enum_to_string(s.rule),
                           json_io::enum_to_string(s.mode), s.seed);
  p.subtitle += fmt::format("step {} (sTime {:.1f} s): eP {:.2f} %, {} / {} free cells visited{}", run_.steps(),
                            run_.sTime(), run_.eP(), run_.visited(), run_.free_cells(),
                            run_.completion_step() ? ", complete" : "");
  return views::exploration_svg(p);
}

}  // namespace swarmcheck::python
