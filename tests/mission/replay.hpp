#pragma once
// Replay of a mission run's trace (tests only): every event enabled in the state it fired in and
// recording the right state after; every region entry seen in the positions fired its event in
// that step; in a world, no position overlaps an obstacle (spec/mission/world.hpp); no two robots
// overlap (distance < sum of radii, spec/mission/separation.hpp); the trace
// ends at a marked state. Returns "" when all hold, else the first broken rule.
#include <algorithm>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "conformance/mission/differential.hpp"
#include "impl/mission/trace.hpp"
#include "spec/mission/avoidance.hpp"
#include "spec/mission/plan.hpp"
#include "spec/mission/sensing.hpp"
#include "spec/mission/world.hpp"
#include "swarmcheck/mission.hpp"

namespace swarmcheck::test {

// A run of the library with the given body, and its JSON Lines trace read back.
struct TracedRun {
  swarmcheck::mission::RunOptions options;
  swarmcheck::mission::RunResult result;
  swarmcheck::impl::mission::MissionTrace trace;
};
inline TracedRun run_traced(const swarmcheck::mission::Mission& m, swarmcheck::mission::BodyModel body) {
  TracedRun out;
  out.options.body = body;
  std::stringstream text;
  swarmcheck::impl::mission::TraceWriter writer(text, m, out.options);
  out.result = swarmcheck::mission::run_mission(m, out.options, &writer);
  out.trace = swarmcheck::impl::mission::read_trace(text, "trace");
  return out;
}

inline std::string replay(const swarmcheck::mission::Mission& m,
                          const swarmcheck::impl::mission::MissionTrace& t) {
  namespace sm = swarmcheck::mission;
  std::string state = t.initial_state;
  std::vector<std::string> fired;  // events since the previous step record
  const sm::StepRecord* prev = nullptr;
  // Unknown obstacles are walls too (spec/mission/sensing.hpp): positions are checked against
  // the world as it is, not the map.
  const std::optional<sm::GridWorld> walls =
      m.world ? std::optional<sm::GridWorld>(sm::true_world(*m.world)) : std::nullopt;
  for (const auto& e : t.entries) {
    if (e.is_event) {
      const auto next = swarmcheck::supervisor::successor(m.fsm, state, e.event.event);
      if (!next) return "event " + e.event.event + " fired in state " + state + ", where it is not enabled";
      if (*next != e.event.state_after) return "event " + e.event.event + " recorded a wrong state";
      state = *next;
      fired.push_back(e.event.event);
      continue;
    }
    if (e.step.state != state) return "step state differs from the replayed state";
    std::vector<std::string> entries;
    for (std::size_t r = 0; r < m.robots.size(); ++r) {
      const sm::Point before = prev ? prev->positions[r] : m.robots[r].start;
      for (const auto& ev : sm::entry_events(m, r, before, e.step.positions[r]))
        entries.push_back(ev);
      if (walls && sm::overlaps_obstacle(*walls, e.step.positions[r], m.robots[r].radius))
        return "robot " + m.robots[r].name + " overlaps an obstacle at t=" + std::to_string(e.step.time_s);
      for (std::size_t o = 0; o < r; ++o)
        if (sm::distance(e.step.positions[r], e.step.positions[o]) < m.robots[r].radius + m.robots[o].radius)
          return "robot " + m.robots[r].name + " overlaps robot " + m.robots[o].name + " at t=" +
                 std::to_string(e.step.time_s);
    }
    if (prev == nullptr) entries = sm::initial_entries(m);
    for (const auto& ev : entries)
      if (std::find(fired.begin(), fired.end(), ev) == fired.end())
        return "a robot entered a region without its event " + ev + " at t=" + std::to_string(e.step.time_s);
    fired.clear();
    prev = &e.step;
  }
  return sm::is_marked(m, state) ? "" : "the trace does not end at a marked state";
}

// What is wrong with a traced run that should be clean: it did not complete, its trace does not
// replay (replay above), or the model's run differs from it; "" when nothing is.
inline std::string unclean(const swarmcheck::mission::Mission& m, const TracedRun& run) {
  if (!run.result.completed) return "not completed: " + run.result.reason;
  if (auto why = replay(m, run.trace); !why.empty()) return why;
  return swarmcheck::conformance::mission::diff_run(m, run.options).value_or("");
}

}  // namespace swarmcheck::test
