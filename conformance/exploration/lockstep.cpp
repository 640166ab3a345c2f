#include "conformance/exploration/lockstep.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "conformance/exploration/observe.hpp"
#include "conformance/exploration/transition.hpp"
#include "model/exploration/exploration_model.hpp"
#include "spec/exploration/controller.hpp"
#include "spec/exploration/neighbourhood.hpp"
#include "spec/util/hana_diff.hpp"

namespace swarmcheck::conformance::exploration {

using namespace swarmcheck::exploration;
using swarmcheck::model::exploration::ExplorationModel;

std::string Divergence::describe() const {
  if (!abnormal_end.empty()) return abnormal_end;   // it names the step
  if (spec_violation) return "step " + std::to_string(step) + ": the model broke the spec: " + impl;
  return "step " + std::to_string(step) + ": " + path + " model=" + model + " impl=" + impl;
}

namespace {

// A difference in an output besides the record, with both sides as observe() shows them.
Divergence derived(const ExplorationModel& m, const Exploration& x, int64_t step, const std::string& path) {
  return Divergence{step, path, observe(m, path).value_or("?"), observe(x, path).value_or("?"), false};
}

std::optional<Divergence> compare_cells(const ExplorationModel& m, const Exploration& x, int64_t step) {
  const int32_t n = m.scenario().map_size;
  for (int32_t i = 0; i < n; ++i)
    for (int32_t j = 0; j < n; ++j) {
      const std::string path = "cells[" + std::to_string(i) + "][" + std::to_string(j) + "]";
      if (auto d = json_io::first_difference(m.cell({i, j}), x.cell({i, j}), path)) return derived(m, x, step, d->path);
    }
  return std::nullopt;
}

// What the user sees besides the record: done(), the completion step.
std::optional<Divergence> compare_outputs(const ExplorationModel& m, const Exploration& x, int64_t step) {
  if (m.done() != x.done()) return derived(m, x, step, "done");
  if (m.completion_step() != x.completion_step()) return derived(m, x, step, "completion_step");
  return std::nullopt;
}

std::optional<Divergence> compare_summaries(const ExplorationModel& m, const Exploration& x, int64_t step) {
  const json_io::Json a = run_summary(m), b = run_summary(x);
  for (auto it = a.begin(); it != a.end(); ++it)
    if (!b.contains(it.key()) || b[it.key()] != it.value()) return derived(m, x, step, "summary." + it.key());
  return std::nullopt;
}

void note_rows(const StepRecord& before, const StepRecord& after, LockstepReach& reach) {
  if (after.planning_steps == before.planning_steps || before.robots.size() != after.robots.size()) return;
  std::vector<int32_t> rows_before, rows_after;
  int64_t changed = 0;
  for (std::size_t r = 0; r < after.robots.size(); ++r) {
    rows_before.push_back(before.robots[r].cell[0]);
    rows_after.push_back(after.robots[r].cell[0]);
    changed += rows_before.back() != rows_after.back() ? 1 : 0;
  }
  std::sort(rows_before.begin(), rows_before.end());
  std::sort(rows_after.begin(), rows_after.end());
  reach.steps_rows_kept += changed == 0 ? 1 : 0;
  reach.steps_one_row_changed += changed == 1 ? 1 : 0;
  reach.steps_rows_exchanged += changed >= 2 && rows_before == rows_after ? 1 : 0;
}

void note_reach(const ExplorationModel& m, const StepRecord& before, const StepRecord& r, LockstepReach& reach) {
  note_rows(before, r, reach);
  reach.steps = r.step;
  reach.planning_steps = r.planning_steps;
  const int32_t n = m.scenario().map_size;
  for (int32_t i = 0; i < n; ++i)
    for (int32_t j = 0; j < n; ++j)
      if (m.cell({i, j}).pheromone != 0.0)
        reach.max_cell_age = std::max(reach.max_cell_age, r.step - m.pheromone_written({i, j}));
  for (const RobotRecord& rr : r.robots)
    if (std::fabs(wrap_angle(rr.body.theta_rad)) > std::numbers::pi - 0.05) reach.heading_near_pi = true;
}

void note_start(const Scenario& s, LockstepReach& reach) {
  for (const Point_m& p : s.robots) {
    if (std::signbit(p[0]) || std::signbit(p[1])) reach.negative_zero_start = true;
    if (p != centre_of(cell_of(p, s.cell_size), s.cell_size)) reach.off_centre_start = true;
  }
}

}  // namespace

std::optional<Divergence> run_lockstep(const Scenario& s, const ExplorationOptions& options, LockstepReach* reach,
                                       CaseProgress* progress) {
  // Which engine computes which step, for a child's parent to say where a crash or a hang was.
  const auto now = [progress](int64_t step, CaseProgress::Side side) {
    if (progress) progress->at(step, side);
  };
  now(0, CaseProgress::Side::model);
  ExplorationModel m(s);
  now(0, CaseProgress::Side::impl);
  Exploration x(s, options);
  if (reach) note_start(s, *reach);
  StepRecord before = m.record();
  if (auto d = json_io::first_difference(before, x.record())) return Divergence{0, d->path, d->a, d->b, false};
  if (auto d = compare_cells(m, x, 0)) return d;
  if (auto d = compare_outputs(m, x, 0)) return d;
  while (!m.done() || !x.done()) {
    now(before.step + 1, CaseProgress::Side::model);
    m.step();
    const StepRecord after = m.record();
    if (std::string e = check_transition(s, before, after); !e.empty()) return Divergence{after.step, "", "", e, true};
    now(before.step + 1, CaseProgress::Side::impl);   // its step and everything read from it
    x.step();
    if (auto d = json_io::first_difference(after, x.record())) return Divergence{after.step, d->path, d->a, d->b, false};
    if (auto d = compare_outputs(m, x, after.step)) return d;
    const bool planned = after.planning_steps != before.planning_steps;
    if (planned || m.done() || after.step % 16 == 0)
      if (auto d = compare_cells(m, x, after.step)) return d;
    if (reach) note_reach(m, before, after, *reach);
    before = after;
  }
  if (reach) reach->completed = m.completion_step().has_value();
  return compare_summaries(m, x, before.step);
}

}  // namespace swarmcheck::conformance::exploration
