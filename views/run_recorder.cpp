#include "views/run_recorder.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "impl/io/atomic_file.hpp"
#include "spec/exploration/trace.hpp"
#include "spec/util/demand.hpp"
#include "views/exploration_svg.hpp"

namespace swarmcheck::views {

using namespace swarmcheck::exploration;
namespace cx = conformance::exploration;

FieldSnapshot field_snapshot(const cx::Simulation& sim, const Scenario& s) {
  FieldSnapshot f;
  f.step = sim.steps();
  f.map_size = s.map_size;
  const std::size_t n = static_cast<std::size_t>(s.map_size);
  f.pheromone.resize(n * n);
  f.visited.resize(n * n);
  for (int32_t i = 0; i < s.map_size; ++i)
    for (int32_t j = 0; j < s.map_size; ++j) {
      const Cell c = sim.cell({i, j});
      const std::size_t k = static_cast<std::size_t>(i) * n + static_cast<std::size_t>(j);
      f.pheromone[k] = c.pheromone;
      f.visited[k] = c.visited;
    }
  return f;
}

RunRecorder::RunRecorder(const Scenario& s, RunRecorderOptions o, std::ostream* trace)
    : scenario_(s), options_(std::move(o)), trace_(trace) {
  SWARM_DEMAND(options_.field_every >= 0);
  SWARM_DEMAND(options_.field_every == 0 || trace_ != nullptr);
  const int64_t cells = int64_t{s.map_size} * s.map_size;
  path_every_ = std::max<int64_t>(1, cells / 4096);
  if (!options_.svg_path.empty()) paths_.resize(s.robots.size());
}

json_io::Json RunRecorder::header(json_io::Json h) const {
  if (options_.field_every == 0) return h;
  h["format_version"] = kTraceFieldFormatVersion;
  h["field_every"] = options_.field_every;
  return h;
}

void RunRecorder::observe(const cx::Simulation& sim) {
  const int64_t step = sim.steps();
  if (options_.field_every > 0 && (step % options_.field_every == 0 || sim.done()))
    *trace_ << field_record(field_snapshot(sim, scenario_)).dump() << '\n';
  if (paths_.empty() || !(step % path_every_ == 0 || sim.done())) return;
  const StepRecord r = sim.record();
  for (std::size_t k = 0; k < r.robots.size(); ++k) {
    const BodyState& b = r.robots[k].body;
    auto& path = paths_[k];
    // Keep a point when the robot has moved a tenth of a cell (cosim paths are dense).
    if (!path.empty() && std::hypot(path.back()[0] - b.x_m, path.back()[1] - b.y_m) < 0.1 * scenario_.cell_size)
      continue;
    path.push_back({b.x_m, b.y_m});
  }
}

void RunRecorder::finish(const cx::Simulation& sim) {
  if (options_.svg_path.empty()) return;
  ExplorationPicture p;
  p.scenario = scenario_;
  p.field = field_snapshot(sim, scenario_);
  p.paths = paths_;
  const StepRecord r = sim.record();
  for (std::size_t k = 0; k < r.robots.size(); ++k) {
    p.poses.push_back(r.robots[k].body);
    p.paths[k].push_back({r.robots[k].body.x_m, r.robots[k].body.y_m});
  }
  p.title = options_.scenario_name;
  p.subtitle = fmt::format("map {}x{}, {} robots, {} obstacles, rule {}, mode {}, seed {}\n", scenario_.map_size,
                           scenario_.map_size, scenario_.robots.size(), scenario_.obstacles.size(),
                           json_io::enum_to_string(scenario_.rule), json_io::enum_to_string(scenario_.mode), scenario_.seed);
  p.subtitle += fmt::format("step {} (sTime {:.1f} s): eP {:.2f} %, {} / {} free cells visited{}", sim.steps(),
                           sim.sTime(), sim.eP(), sim.visited(), sim.free_cells(),
                           sim.completion_step() ? ", complete" : "");
  io::write_file_atomically(options_.svg_path, exploration_svg(p));
}

}  // namespace swarmcheck::views
