// check_mission: resolves a MissionDecl against its FSM and checks it before anything runs.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>
#include <unordered_map>

#include "spec/mission/mission.hpp"
#include "spec/mission/separation.hpp"
#include "spec/mission/world.hpp"
#include "spec/supervisor/semantics.hpp"
#include "spec/util/input_error.hpp"

namespace swarmcheck::mission {

namespace {

std::string list_names(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out.empty() ? "none" : out;
}

template <class T>
std::vector<std::string> names_of(const std::vector<T>& xs) {
  std::vector<std::string> out;
  for (const auto& x : xs) out.push_back(x.name);
  return out;
}

// Names to their index in a list. (The checks looked names up by scanning the lists: 200 000
// regions, each with its entry event, took minutes.)
using NameIndex = std::unordered_map<std::string, std::size_t>;

// The index of each name; the first repeated name refused.
template <class T>
NameIndex unique_names(const std::vector<T>& xs, const std::string& list) {
  NameIndex index;
  for (std::size_t i = 0; i < xs.size(); ++i)
    if (const auto [at, fresh] = index.emplace(xs[i].name, i); !fresh)
      throw InputError(fmt::format("{}[{}].name", list, i),
                       fmt::format("\"{}\" is already the name of {}[{}]", xs[i].name, list, at->second));
  return index;
}

template <class T>
std::size_t resolve(const std::vector<T>& xs, const NameIndex& index, const std::string& name,
                    const std::string& path, const char* what) {
  if (const auto it = index.find(name); it != index.end()) return it->second;
  throw InputError(path, fmt::format("no {} named \"{}\" ({}s: {})", what, name, what,
                                     list_names(names_of(xs))));
}

struct DeclNames {
  NameIndex robots, tasks, regions;
};

std::string fmt_point(const Point& p) { return fmt::format("[{}, {}]", p[0], p[1]); }

Region check_region(const RegionDecl& d, std::size_t i) {
  const Point& a = d.corners[0];
  const Point& b = d.corners[1];
  const char* zero = a[0] == b[0] ? "width" : (a[1] == b[1] ? "height" : nullptr);
  if (zero)
    throw InputError(fmt::format("regions[{}].corners", i),
                     fmt::format("the corners {} and {} give a rectangle of zero {} (expected two "
                                 "opposite corners with different x and different y)",
                                 fmt_point(a), fmt_point(b), zero));
  return Region{d.name, {std::min(a[0], b[0]), std::min(a[1], b[1])},
                {std::max(a[0], b[0]), std::max(a[1], b[1])}};
}

void check_state(const supervisor::Automaton& fsm, const std::string& q, const std::string& path,
                 const std::string& fsm_name) {
  if (!fsm.delta.count(q) && std::find(fsm.states.begin(), fsm.states.end(), q) == fsm.states.end())
    throw InputError(path, fmt::format("state \"{}\" is not in {}", q, fsm_name));
}

Meaning resolve_meaning(const std::string& event, const MeaningDecl& d, const MissionDecl& m, const DeclNames& names) {
  const std::string path = "events." + event;
  if (d.task.has_value() == d.region.has_value())
    throw InputError(path, "expected exactly one of \"task\" (a task start) or \"region\" (a "
                           "region entry)");
  const std::size_t robot = resolve(m.robots, names.robots, d.robot, path + ".robot", "robot");
  if (d.task)
    return Meaning{MeaningKind::task_start, robot, resolve(m.tasks, names.tasks, *d.task, path + ".task", "task")};
  return Meaning{MeaningKind::region_entry, robot,
                 resolve(m.regions, names.regions, *d.region, path + ".region", "region")};
}

void check_events(const Mission& m) {
  // The first event (in name order) of each meaning: a later one with the same meaning names it.
  std::map<std::tuple<MeaningKind, std::size_t, std::size_t>, std::string> first_with;
  for (const auto& [event, meaning] : m.events) {
    const auto it = m.fsm.events.find(event);
    const bool c = it->second.controllable;
    if (meaning.kind == MeaningKind::task_start && !c)
      throw InputError("events." + event,
                       fmt::format("starts a task, so it must be controllable, but {} declares it "
                                   "uncontrollable (uc)", m.fsm_name));
    if (meaning.kind == MeaningKind::region_entry && c)
      throw InputError("events." + event,
                       fmt::format("is a region entry, which the robots cause, so it must be "
                                   "uncontrollable, but {} declares it controllable (c)",
                                   m.fsm_name));
    const auto [first, fresh] = first_with.emplace(std::tuple{meaning.kind, meaning.robot, meaning.target}, event);
    if (!fresh)
      throw InputError("events." + event, fmt::format("has the same meaning as events.{}", first->second));
  }
  for (const auto& [event, attr] : m.fsm.events)
    if (!m.events.count(event))
      throw InputError("events", fmt::format("event \"{}\" of {} has no meaning (expected "
                                             "\"{}\": {{\"robot\": ..., \"task\": ...}} or "
                                             "{{\"robot\": ..., \"region\": ...}})",
                                             event, m.fsm_name, event));
}

void check_starts(const Mission& m) {
  std::string q = m.initial_state;
  std::vector<std::string> fired;
  for (std::size_t r = 0; r < m.robots.size(); ++r)
    for (std::size_t g = 0; g < m.regions.size(); ++g) {
      if (!inside(m.regions[g], m.robots[r].start)) continue;
      const std::string* e = event_for(m, MeaningKind::region_entry, r, g);
      if (!e) continue;
      const auto next = supervisor::successor(m.fsm, q, *e);
      if (!next)
        throw InputError(
            fmt::format("robots[{}].start", r),
            fmt::format("robot {} starts inside region {}, so its entry event {} fires at the "
                        "start, but {} is not enabled in state {}{}",
                        m.robots[r].name, m.regions[g].name, *e, *e, q,
                        fired.empty() ? std::string(" (the initial state)")
                                      : " (after " + list_names(fired) + ")"));
      fired.push_back(*e);
      q = *next;
    }
}

void check_reachable(const Mission& m) {
  supervisor::StateSet seen{m.initial_state};
  for (;;) {
    const auto next = supervisor::post(m.fsm, seen);
    const std::size_t before = seen.size();
    seen.insert(next.begin(), next.end());
    if (seen.size() == before) break;
  }
  for (const auto& q : m.marked_states)
    if (seen.count(q)) return;
  throw InputError("marked_states",
                   fmt::format("no marked state is reachable from the initial state {} in {}",
                               m.initial_state, m.fsm_name));
}

}  // namespace

Mission check_mission(const MissionDecl& d, const supervisor::Automaton& fsm,
                      const std::string& file) {
  try {
    Mission m;
    m.source = file;
    m.fsm_name = d.fsm;
    m.fsm = fsm;
    if (d.robots.empty()) throw InputError("robots", "expected at least one robot");
    const DeclNames names{unique_names(d.robots, "robots"), unique_names(d.tasks, "tasks"),
                          unique_names(d.regions, "regions")};
    for (std::size_t i = 0; i < d.robots.size(); ++i) {
      const double radius = i < d.radii.size() ? d.radii[i] : 0.0;
      if (!std::isfinite(radius) || radius < 0.0 || radius > 1e6)
        throw InputError(fmt::format("robots[{}].radius", i),
                         fmt::format("expected a radius in metres, >= 0 and at most 1e6; got {}",
                                     radius));
      m.robots.push_back(Robot{d.robots[i].name, d.robots[i].start, radius});
    }
    for (const auto& t : d.tasks) m.tasks.push_back(Task{t.name, t.at});
    for (std::size_t i = 0; i < d.regions.size(); ++i) m.regions.push_back(check_region(d.regions[i], i));
    if (d.world) {
      m.world = build_world(*d.world);
      for (std::size_t i = 0; i < m.robots.size(); ++i) {
        const double radius = m.robots[i].radius;
        if (traversable_checks(*m.world, radius) > kMaxTraversableChecks)
          throw InputError(fmt::format("robots[{}].radius", i),
                           fmt::format("a radius of {} m in a world of {} x {} cells of {} m needs "
                                       "{} neighbour checks to find its free cells; at most {} "
                                       "(use larger cells or a smaller world)",
                                       radius, m.world->rows, m.world->cols,
                                       m.world->resolution_m,
                                       traversable_checks(*m.world, radius),
                                       kMaxTraversableChecks));
        m.world->traversable.push_back(traversable_cells(*m.world, radius));
      }
    }
    check_state(fsm, d.initial_state, "initial_state", d.fsm);
    m.initial_state = d.initial_state;
    if (d.marked_states.empty())
      throw InputError("marked_states", "expected at least one marked state");
    for (std::size_t i = 0; i < d.marked_states.size(); ++i)
      check_state(fsm, d.marked_states[i], fmt::format("marked_states[{}]", i), d.fsm);
    m.marked_states = d.marked_states;
    for (const auto& [event, meaning] : d.events) {
      const Meaning mn = resolve_meaning(event, meaning, d, names);
      if (fsm.events.count(event))
        m.events.emplace(event, mn);
      else
        m.unused_events.push_back(event);
    }
    check_events(m);
    check_world(m);
    check_robots_apart(m);
    check_starts(m);
    check_reachable(m);
    return m;
  } catch (const InputError& e) {
    throw InputError(file + ": " + e.where(), std::string(e.what()).substr(e.where().size() + 2));
  }
}

}  // namespace swarmcheck::mission
