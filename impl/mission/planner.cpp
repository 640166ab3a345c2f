// The exact mission planner: Pareto label setting, best first on (makespan, total).
#include "impl/mission/planner.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <memory>
#include <queue>
#include <tuple>
#include <unordered_map>

#include "impl/supervisor/reach.hpp"
#include "spec/mission/run.hpp"
#include "spec/mission/world.hpp"
#include "swarmcheck/mission.hpp"
#include "spec/util/input_error.hpp"

namespace swarmcheck::impl::mission {

namespace {

using supervisor::EventId;
using supervisor::StateId;
namespace sm = swarmcheck::mission;

constexpr std::uint32_t kNoLabel = UINT32_MAX;

template <class T>
void append_bytes(std::string& out, const T& v) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  out.append(b, sizeof(T));
}

struct Label {
  StateId state;
  std::uint32_t parent;
  EventId event;
  std::uint32_t length;
  double makespan;
  double total;
};

struct Key {  // (makespan, total, length, creation): smaller pops first
  double makespan, total;
  std::uint32_t length, id;
  bool operator>(const Key& o) const {
    return std::tie(makespan, total, length, id) > std::tie(o.makespan, o.total, o.length, o.id);
  }
};

// The labels of one search: per-robot positions and travel stored flat, the open queue, and the
// labels settled at each node (state, positions), for the Pareto dominance test.
struct Labels {
  explicit Labels(std::size_t robots_count) : robots(robots_count) {}

  const std::uint16_t* pos_of(std::uint32_t id) const { return &pos[std::size_t{id} * robots]; }
  const double* travel_of(std::uint32_t id) const { return &travel[std::size_t{id} * robots]; }

  std::string node_key(StateId s, const std::uint16_t* ps) const {
    std::string k;
    append_bytes(k, s);
    k.append(reinterpret_cast<const char*>(ps), robots * sizeof(std::uint16_t));
    return k;
  }

  // Some label settled at node k has travel <= v robot by robot.
  bool dominated(const std::string& k, const double* v) const {
    const auto it = settled.find(k);
    if (it == settled.end()) return false;
    for (const std::uint32_t w : it->second) {
      const double* tw = travel_of(w);
      bool all_le = true;
      for (std::size_t r = 0; r < robots && all_le; ++r) all_le = tw[r] <= v[r];
      if (all_le) return true;
    }
    return false;
  }

  void push(const Label& l, const std::uint16_t* ps, const double* tv) {
    const auto id = static_cast<std::uint32_t>(all.size());
    all.push_back(l);
    pos.insert(pos.end(), ps, ps + robots);
    travel.insert(travel.end(), tv, tv + robots);
    open.push(Key{l.makespan, l.total, l.length, id});
  }

  std::size_t robots;
  std::vector<Label> all;
  std::vector<std::uint16_t> pos;  // [label * robots + r]
  std::vector<double> travel;      // [label * robots + r]
  std::priority_queue<Key, std::vector<Key>, std::greater<>> open;
  std::unordered_map<std::string, std::vector<std::uint32_t>> settled;
};

// The plan that label `id` ends: its events read back along the parents, its travel's cost.
Plan plan_of(const Labels& labels, std::uint32_t id, const supervisor::Fsm& fsm) {
  Plan out;
  out.found = true;
  out.final_state = fsm.state_names[labels.all[id].state];
  const double* tv = labels.travel_of(id);
  out.cost = sm::cost_of(std::vector<double>(tv, tv + labels.robots));
  for (std::uint32_t at = id; labels.all[at].parent != kNoLabel; at = labels.all[at].parent)
    out.events.push_back(fsm.event_names[labels.all[at].event]);
  std::reverse(out.events.begin(), out.events.end());
  return out;
}

}  // namespace

Planner::Planner(const sm::Mission& m) : mission_(&m), fsm_(supervisor::compile(m.fsm)) {
  const StateId n = fsm_.state_count();
  for (StateId s = 0; s < n; ++s) state_id_.emplace(fsm_.state_names[s], s);
  marked_.assign(n, 0);
  for (const auto& q : m.marked_states)
    if (auto it = state_id_.find(q); it != state_id_.end()) marked_[it->second] = 1;
  // Only states that can still reach a marked state are ever entered.
  coaccessible_ = supervisor::coreachable(supervisor::reverse_edges(fsm_), marked_);
  event_robot_.assign(fsm_.event_count(), -1);
  event_task_.assign(fsm_.event_count(), -1);
  for (EventId e = 0; e < fsm_.event_count(); ++e) {
    const auto it = m.events.find(fsm_.event_names[e]);
    if (it != m.events.end() && it->second.kind == sm::MeaningKind::task_start) {
      event_robot_[e] = static_cast<std::int32_t>(it->second.robot);
      event_task_[e] = static_cast<std::int32_t>(it->second.target);
    }
  }
  const std::size_t t = m.tasks.size(), robots = m.robots.size();
  task_slot_.assign(robots * t, -1);
  std::vector<std::vector<std::size_t>> own(robots);   // each robot's tasks, in event order
  for (EventId e = 0; e < fsm_.event_count(); ++e)
    if (event_robot_[e] >= 0) {
      const auto r = static_cast<std::size_t>(event_robot_[e]);
      const auto task = static_cast<std::size_t>(event_task_[e]);
      if (task_slot_[r * t + task] < 0) {
        task_slot_[r * t + task] = static_cast<std::int32_t>(own[r].size());
        own[r].push_back(task);
      }
    }
  robot_task_count_.resize(robots);
  distance_at_.resize(robots);
  std::size_t size = 0;
  for (std::size_t r = 0; r < robots; ++r) {
    robot_task_count_[r] = own[r].size();
    distance_at_[r] = size;
    size += own[r].size() * own[r].size();
  }
  task_distance_.resize(size);
  for (std::size_t r = 0; r < robots; ++r)
    for (std::size_t a = 0; a < own[r].size(); ++a)
      for (std::size_t b = 0; b < own[r].size(); ++b)
        task_distance_[distance_at_[r] + a * own[r].size() + b] = sm::travel_cost(m, r, m.tasks[own[r][a]].at, m.tasks[own[r][b]].at);
}

double Planner::cost_from(std::size_t r, const sm::Point& p, std::size_t t) {
  const sm::Mission& m = *mission_;
  if (!m.world) return sm::distance(p, m.tasks[t].at);
  const auto key = std::make_tuple(r, std::bit_cast<std::uint64_t>(p[0]),
                                   std::bit_cast<std::uint64_t>(p[1]), t);
  if (const auto it = route_memo_.find(key); it != route_memo_.end()) return it->second;
  const double c = sm::travel_cost(m, r, p, m.tasks[t].at);
  route_memo_.emplace(key, c);
  return c;
}

Plan Planner::plan(const PlanQuery& q) {
  const std::size_t robots = mission_->robots.size();
  if (q.positions.size() != robots || q.travel.size() != robots)
    throw InputError("plan query", "expected one position and one travel per robot");
  if (!state_id_.count(q.from))
    throw InputError("plan query", "state \"" + q.from + "\" is not in " + mission_->fsm_name);
  std::string key = q.from;
  key.push_back('\0');
  for (std::size_t r = 0; r < robots; ++r) {
    append_bytes(key, q.positions[r][0]);
    append_bytes(key, q.positions[r][1]);
    append_bytes(key, q.travel[r]);
  }
  if (const auto it = cache_.find(key); it != cache_.end()) {
    ++cache_hits_;
    return it->second;
  }
  Plan p = search(q);
  if (cache_.size() >= sm::kPlanMemory) cache_.clear();  // the spec's memory of queries
  cache_.emplace(std::move(key), p);
  return p;
}

Plan Planner::search(const PlanQuery& q) {
  const sm::Mission& m = *mission_;
  const std::size_t robots = m.robots.size();
  const std::size_t tasks = m.tasks.size();
  const std::uint16_t here = static_cast<std::uint16_t>(tasks);  // "at the query position"
  // Distance from each robot's query position to each task, for this query only.
  std::vector<double> from_here(robots * tasks);
  for (std::size_t r = 0; r < robots; ++r)
    for (std::size_t t = 0; t < tasks; ++t)
      from_here[r * tasks + t] = cost_from(r, q.positions[r], t);

  Labels labels(robots);
  const StateId start = state_id_.at(q.from);
  if (coaccessible_[start]) {
    const sm::PlanCost c0 = sm::cost_of(q.travel);
    const std::vector<std::uint16_t> p0(robots, here);
    labels.push(Label{start, kNoLabel, 0, 0, c0.makespan, c0.total}, p0.data(), q.travel.data());
  }
  Plan out;
  std::vector<std::uint16_t> ps(robots);
  std::vector<double> tv(robots);
  while (!labels.open.empty()) {
    const std::uint32_t id = labels.open.top().id;
    labels.open.pop();
    const Label l = labels.all[id];
    const std::string k = labels.node_key(l.state, labels.pos_of(id));
    if (labels.dominated(k, labels.travel_of(id))) continue;
    labels.settled[k].push_back(id);
    if (marked_[l.state]) {
      out = plan_of(labels, id, fsm_);
      break;
    }
    for (auto e = fsm_.first_edge[l.state]; e < fsm_.first_edge[l.state + 1]; ++e) {
      const StateId target = fsm_.edge_target[e];
      if (!coaccessible_[target]) continue;
      const EventId ev = fsm_.edge_event[e];
      std::copy_n(labels.pos_of(id), robots, ps.begin());
      std::copy_n(labels.travel_of(id), robots, tv.begin());
      if (event_robot_[ev] >= 0) {  // a task start: that robot travels to the task
        const auto r = static_cast<std::size_t>(event_robot_[ev]);
        const auto t = static_cast<std::uint16_t>(event_task_[ev]);
        tv[r] += ps[r] == here ? from_here[r * tasks + t] : task_distance(r, ps[r], t);
        ps[r] = t;
      }
      double makespan = 0.0, total = 0.0;  // as spec cost_of does, without its copy
      for (const double x : tv) {
        makespan = std::max(makespan, x);
        total += x;
      }
      if (labels.dominated(labels.node_key(target, ps.data()), tv.data())) continue;
      labels.push(Label{target, id, ev, l.length + 1, makespan, total}, ps.data(), tv.data());
    }
  }
  labels_last_ = labels.all.size();
  return out;
}

}  // namespace swarmcheck::impl::mission

namespace swarmcheck::mission {

// The public planner owns its copy of the mission, which the internal one points into.
struct Planner::State {
  explicit State(const Mission& mission) : m(mission), planner(m) {}
  Mission m;
  impl::mission::Planner planner;
};

Planner::Planner(const Mission& m) : state_(std::make_unique<State>(m)) {}
Planner::~Planner() = default;
Planner::Planner(Planner&&) noexcept = default;
Planner& Planner::operator=(Planner&&) noexcept = default;
Plan Planner::plan(const PlanQuery& q) { return state_->planner.plan(q); }
std::size_t Planner::cache_hits() const { return state_->planner.cache_hits(); }
std::size_t Planner::labels_last() const { return state_->planner.labels_last(); }

}  // namespace swarmcheck::mission
