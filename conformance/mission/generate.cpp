// Generated missions for properties, comparisons and benchmarks.
#include "conformance/mission/generate.hpp"

#include <cmath>
#include <map>
#include <random>
#include <string>
#include <tuple>

namespace swarmcheck::conformance::mission {

namespace sm = swarmcheck::mission;
namespace sv = swarmcheck::supervisor;

namespace {

sm::Mission skeleton(std::size_t robots, const std::vector<sm::Point>& starts,
                     const std::vector<sm::Point>& tasks) {
  sm::Mission m;
  m.source = "generated";
  m.fsm_name = "generated.fsm";
  for (std::size_t r = 0; r < robots; ++r)
    m.robots.push_back(sm::Robot{"R" + std::to_string(r), starts[r]});
  for (std::size_t t = 0; t < tasks.size(); ++t)
    m.tasks.push_back(sm::Task{"t" + std::to_string(t), tasks[t]});
  return m;
}

}  // namespace

namespace {

rc::Gen<sm::Point> any_point() {
  auto coord = rc::gen::map(rc::gen::inRange(-10, 11), [](int v) { return double(v); });
  return rc::gen::apply([](double x, double y) { return sm::Point{x, y}; }, coord, coord);
}

rc::Gen<sm::Point> lattice_point() {
  return rc::gen::apply([](double x, double y) { return sm::Point{x, y}; }, rc::gen::element(-3.0, 0.0, 3.0),
                        rc::gen::element(-4.0, 0.0, 4.0));
}

// Starts inside a region would fire its entry at time 0, which the FSM may not enable (the
// mission checker refuses that): a start inside the region around x, y > 0 or x, y < 0 is
// mirrored across the x axis (outside both), one on a task's square moved 8 m down.
void starts_outside_regions(sm::Mission& m) {
  for (auto& r : m.robots)
    for (int pass = 0; pass < 4; ++pass)
      for (const auto& g : m.regions)
        if (sm::inside(g, r.start)) r.start[1] = g.hi[0] - g.lo[0] == 10 ? -r.start[1] : r.start[1] - 8;
}

sm::Mission small_mission(const rc::Gen<sm::Point>& point) {
  return *rc::gen::exec([point] {
    const auto robots = *rc::gen::inRange<std::size_t>(1, 4);
    const auto ntasks = *rc::gen::inRange<std::size_t>(1, 4);
    const auto states = *rc::gen::inRange<std::size_t>(2, 7);
    std::vector<sm::Point> starts, tasks;
    for (std::size_t r = 0; r < robots; ++r) starts.push_back(*point);
    for (std::size_t t = 0; t < ntasks; ++t) tasks.push_back(*point);
    sm::Mission m = skeleton(robots, starts, tasks);
    m.regions = {sm::Region{"g0", {-10, -10}, {0, 0}}, sm::Region{"g1", {0, 0}, {10, 10}}};
    std::vector<std::string> names;
    for (std::size_t r = 0; r < robots; ++r) {
      for (std::size_t t = 0; t < ntasks; ++t) {
        const std::string e = "r" + std::to_string(r) + "t" + std::to_string(t);
        m.events[e] = sm::Meaning{sm::MeaningKind::task_start, r, t};
        m.fsm.events[e] = sv::EventAttr{true, true};
        names.push_back(e);
      }
      for (std::size_t g = 0; g < 2; ++g) {
        const std::string e = "r" + std::to_string(r) + "g" + std::to_string(g);
        m.events[e] = sm::Meaning{sm::MeaningKind::region_entry, r, g};
        m.fsm.events[e] = sv::EventAttr{false, true};
        names.push_back(e);
      }
    }
    for (std::size_t q = 0; q < states; ++q) m.fsm.states.push_back("q" + std::to_string(q));
    for (std::size_t q = 0; q < states; ++q) {
      const auto edges = *rc::gen::inRange<std::size_t>(0, 4);
      for (std::size_t k = 0; k < edges; ++k) {
        const auto e = *rc::gen::inRange<std::size_t>(0, names.size());
        const auto to = *rc::gen::inRange<std::size_t>(0, states);
        m.fsm.delta[m.fsm.states[q]][names[e]] = m.fsm.states[to];
      }
    }
    const auto marked = *rc::gen::inRange<std::size_t>(1, 3);
    for (std::size_t k = 0; k < marked; ++k) {
      const auto q = *rc::gen::inRange<std::size_t>(0, states);
      if (!m.fsm.marked.count(m.fsm.states[q])) {
        m.fsm.marked.insert(m.fsm.states[q]);
        m.marked_states.push_back(m.fsm.states[q]);
      }
    }
    m.initial_state = m.fsm.states[0];
    starts_outside_regions(m);
    return m;
  });
}

}  // namespace

rc::Gen<sm::Mission> random_small_mission() {
  return rc::gen::exec([] { return small_mission(any_point()); });
}

// Branches from q0 to the one marked state, each 1..3 events: task starts of random robots, and
// region entries (no cost, but a longer path), so that branches tie on the makespan on the
// lattice while their totals and lengths differ.
rc::Gen<sm::Mission> tie_mission() {
  return rc::gen::exec([] {
    sm::Mission m = small_mission(lattice_point());
    m.fsm.delta.clear();
    m.fsm.marked.clear();
    m.marked_states.clear();
    std::vector<std::string> starts, entries;
    for (const auto& [e, attr] : m.fsm.events) (attr.controllable ? starts : entries).push_back(e);
    const std::string goal = m.fsm.states.back();
    m.fsm.marked.insert(goal);
    m.marked_states.push_back(goal);
    // Each branch: 1..2 task starts and 0..2 region entries, in a random order, through states
    // of its own.
    const auto branches = *rc::gen::inRange<std::size_t>(2, 5);
    for (std::size_t b = 0; b < branches; ++b) {
      std::vector<std::string> path;
      const auto n_starts = *rc::gen::inRange<std::size_t>(1, 3), n_entries = *rc::gen::inRange<std::size_t>(0, 3);
      for (std::size_t k = 0; k < n_starts; ++k) path.push_back(starts[*rc::gen::inRange<std::size_t>(0, starts.size())]);
      for (std::size_t k = 0; k < n_entries; ++k)
        path.insert(path.begin() + static_cast<long>(*rc::gen::inRange<std::size_t>(0, path.size() + 1)),
                    entries[*rc::gen::inRange<std::size_t>(0, entries.size())]);
      std::string at = m.fsm.states.front();
      for (std::size_t k = 0; k < path.size(); ++k) {
        std::string to = goal;
        if (k + 1 < path.size()) {
          to = "b" + std::to_string(b) + "_" + std::to_string(k);
          m.fsm.states.push_back(to);
        }
        m.fsm.delta[at][path[k]] = to;
        at = to;
      }
    }
    // Two more branches that tie on purpose, when two robots have tasks away from their starts:
    // [entry, a, entry] and [a, b], b another robot's task no farther away than a's. The same
    // makespan; the longer path has the smaller total, so a planner that orders equal makespans
    // by anything but the total first returns the larger total. (Drawn at random, the branches
    // above seldom make such a pair: the fault label-order-length-before-total was caught after
    // 184 tie missions with seed 1, and missed in 300 cases of seeds 1, 2 and 3 once the mission
    // campaign drew the sensing kind too.) Added last, they replace a branch above that leaves q0
    // on the same event.
    std::vector<std::tuple<std::string, std::size_t, double>> away;   // task start, robot, distance
    for (const auto& [e, meaning] : m.events)
      if (meaning.kind == sm::MeaningKind::task_start) {
        const sm::Point& s = m.robots[meaning.robot].start;
        const sm::Point& t = m.tasks[meaning.target].at;
        const double d = std::hypot(t[0] - s[0], t[1] - s[1]);
        if (d > 0) away.emplace_back(e, meaning.robot, d);
      }
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    for (std::size_t i = 0; i < away.size(); ++i)
      for (std::size_t j = 0; j < away.size(); ++j)
        if (std::get<1>(away[i]) != std::get<1>(away[j]) && std::get<2>(away[j]) <= std::get<2>(away[i]))
          pairs.emplace_back(i, j);
    if (!pairs.empty()) {
      const auto [i, j] = pairs[*rc::gen::inRange<std::size_t>(0, pairs.size())];
      const std::string& a = std::get<0>(away[i]);
      const std::string& entry = entries[*rc::gen::inRange<std::size_t>(0, entries.size())];
      const std::vector<std::vector<std::string>> paths{{entry, a, entry}, {a, std::get<0>(away[j])}};
      for (std::size_t p = 0; p < paths.size(); ++p) {
        std::string at = m.fsm.states.front();
        for (std::size_t k = 0; k < paths[p].size(); ++k) {
          std::string to = goal;
          if (k + 1 < paths[p].size()) {
            to = "tie" + std::to_string(p) + "_" + std::to_string(k);
            m.fsm.states.push_back(to);
          }
          m.fsm.delta[at][paths[p][k]] = to;
          at = to;
        }
      }
    }
    return m;
  });
}

// Robots 0 and 1 split tasks t1 and t2 either way, the FSM reconverges, then r0 does t0, r1 does t3,
// and r0 does t4: one (state, positions) node reached with two different travel vectors, where
// only the robot-by-robot dominance keeps the label whose continuation is better.
rc::Gen<sm::Mission> swap_mission() {
  return rc::gen::exec([] {
    const auto point = *rc::gen::element(0, 1) == 0 ? lattice_point() : any_point();
    std::vector<sm::Point> starts{*point, *point}, tasks;
    for (int t = 0; t < 5; ++t) tasks.push_back(*point);
    sm::Mission m = skeleton(2, starts, tasks);
    auto start = [&](std::size_t r, std::size_t t) {
      const std::string e = "r" + std::to_string(r) + "t" + std::to_string(t);
      m.events[e] = sm::Meaning{sm::MeaningKind::task_start, r, t};
      m.fsm.events[e] = sv::EventAttr{true, true};
      return e;
    };
    for (const char* q : {"q0", "qa", "qb", "qc", "qd", "qe", "qm"}) m.fsm.states.push_back(q);
    m.fsm.delta["q0"][start(0, 1)] = "qa";
    m.fsm.delta["q0"][start(0, 2)] = "qb";
    m.fsm.delta["qa"][start(1, 2)] = "qc";
    m.fsm.delta["qb"][start(1, 1)] = "qc";
    m.fsm.delta["qc"][start(0, 0)] = "qd";
    m.fsm.delta["qd"][start(1, 3)] = "qe";
    m.fsm.delta["qe"][start(0, 4)] = "qm";
    m.fsm.marked.insert("qm");
    m.marked_states.push_back("qm");
    m.initial_state = "q0";
    return m;
  });
}

sm::Mission allocation_mission(std::size_t robots, std::size_t tasks, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-20.0, 20.0);
  std::vector<sm::Point> starts, points;
  for (std::size_t r = 0; r < robots; ++r) starts.push_back({u(rng), u(rng)});
  for (std::size_t t = 0; t < tasks; ++t) points.push_back({u(rng), u(rng)});
  return allocation_mission_at(starts, points);
}

rc::Gen<sm::Mission> small_allocation_mission() {
  return rc::gen::exec([] {
    const auto robots = *rc::gen::inRange<std::size_t>(2, 4);
    const auto tasks = *rc::gen::inRange<std::size_t>(2, robots == 3 ? 3 : 4);
    const auto point = *rc::gen::element(0, 1) == 0 ? lattice_point() : any_point();
    std::vector<sm::Point> starts, points;
    for (std::size_t r = 0; r < robots; ++r) starts.push_back(*point);
    for (std::size_t t = 0; t < tasks; ++t) points.push_back(*point);
    sm::Mission m = allocation_mission_at(starts, points);
    starts_outside_regions(m);
    return m;
  });
}

sm::Mission allocation_mission_at(const std::vector<sm::Point>& starts, const std::vector<sm::Point>& points,
                                  std::size_t capacity, std::size_t per_robot) {
  const std::size_t robots = starts.size(), tasks = points.size();
  sm::Mission m = skeleton(robots, starts, points);
  for (std::size_t t = 0; t < tasks; ++t)
    m.regions.push_back(sm::Region{"reg" + std::to_string(t),
                                   {points[t][0] - 1, points[t][1] - 1},
                                   {points[t][0] + 1, points[t][1] + 1}});
  auto ev = [](char kind, std::size_t r, std::size_t t) {
    return "r" + std::to_string(r) + kind + std::to_string(t);
  };
  for (std::size_t r = 0; r < robots; ++r)
    for (std::size_t t = 0; t < tasks; ++t) {
      m.events[ev('s', r, t)] = sm::Meaning{sm::MeaningKind::task_start, r, t};
      m.events[ev('f', r, t)] = sm::Meaning{sm::MeaningKind::region_entry, r, t};
      m.fsm.events[ev('s', r, t)] = sv::EventAttr{true, true};
      m.fsm.events[ev('f', r, t)] = sv::EventAttr{false, true};
    }
  // Task status: 0 free, 1 done, 2 + r in progress by r. Breadth-first from all free.
  auto name = [](const std::vector<std::size_t>& s) {
    std::string n = "s";
    for (const auto v : s) n += std::to_string(v) + ".";
    return n;
  };
  std::map<std::vector<std::size_t>, bool> seen;
  std::vector<std::vector<std::size_t>> queue{std::vector<std::size_t>(tasks, 0)};
  seen[queue[0]] = true;
  for (std::size_t k = 0; k < queue.size(); ++k) {
    const auto s = queue[k];
    const std::string q = name(s);
    m.fsm.states.push_back(q);
    bool all_done = true;
    for (const auto v : s) all_done = all_done && v == 1;
    if (all_done) {
      m.fsm.marked.insert(q);
      m.marked_states.push_back(q);
    }
    auto push = [&](std::vector<std::size_t> next, const std::string& e) {
      m.fsm.delta[q][e] = name(next);
      if (!seen.count(next)) {
        seen[next] = true;
        queue.push_back(std::move(next));
      }
    };
    std::size_t working = 0;
    for (const auto v : s) working += v >= 2 ? 1 : 0;
    for (std::size_t r = 0; r < robots; ++r) {
      std::size_t mine = 0;
      for (const auto v : s) mine += v == 2 + r ? 1 : 0;
      const bool busy = working >= capacity || mine >= per_robot;
      for (std::size_t t = 0; t < tasks; ++t) {
        if (s[t] == 2 + r) {
          auto next = s;
          next[t] = 1;
          push(next, ev('f', r, t));
        } else if (!busy && s[t] == 0) {
          auto next = s;
          next[t] = 2 + r;
          push(next, ev('s', r, t));
        }
      }
    }
  }
  m.initial_state = m.fsm.states[0];
  return m;
}

}  // namespace swarmcheck::conformance::mission
