// The thesis's Calculate Costs and modified Dijkstra, as the MATLAB of Appendices J and K.
#include "model/mission/thesis_dijkstra.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "spec/mission/world.hpp"

namespace swarmcheck::model::mission {

namespace {

namespace sm = swarmcheck::mission;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct EventInfo {
  char type = 'e';     // 's' task start, 'f' task-region entry, 'e' other region entry
  std::size_t bot = 0;
  std::size_t task = 0;  // for 's' and 'f'
};

EventInfo info_of(const sm::Mission& m, const std::string& event) {
  const sm::Meaning& mn = m.events.at(event);
  EventInfo in;
  in.bot = mn.robot;
  if (mn.kind == sm::MeaningKind::task_start) {
    in.type = 's';
    in.task = mn.target;
    return in;
  }
  for (std::size_t t = 0; t < m.tasks.size(); ++t)
    if (sm::inside(m.regions[mn.target], m.tasks[t].at)) {
      in.type = 'f';
      in.task = t;
      break;
    }
  return in;
}

struct Matrices {
  std::size_t n = 0;
  std::vector<std::vector<std::size_t>> next;           // neighbours J of I, ascending
  std::map<std::pair<std::size_t, std::size_t>, double> cost;         // C(I, J)
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> bot;    // bot(I, J)
  std::map<std::pair<std::size_t, std::size_t>, std::string> event;   // the event I -> J
};

// func_calculateCosts.
Matrices calculate_costs(const sm::Mission& m, const sm::PlanQuery& q,
                         const std::map<std::string, std::size_t>& index) {
  const auto& states = m.fsm.states;
  Matrices x;
  x.n = states.size();
  auto edges_of = [&](std::size_t i) -> const std::map<std::string, std::string>* {
    const auto it = m.fsm.delta.find(states[i]);
    return it == m.fsm.delta.end() ? nullptr : &it->second;
  };
  auto start_distance = [&](const EventInfo& e) {
    return sm::travel_cost(m, e.bot, q.positions[e.bot], m.tasks[e.task].at);
  };
  std::vector<std::string> task_finished(x.n);
  for (std::size_t i = 0; i < x.n; ++i) {
    const auto* edges = edges_of(i);
    if (!edges) continue;
    for (const auto& [event, target] : *edges) {
      const bool controllable = m.fsm.events.at(event).controllable;
      const EventInfo me = info_of(m, event);
      if (controllable) {
        for (std::size_t j = 0; j < x.n; ++j) {
          const auto* other = edges_of(j);
          if (!other) continue;
          for (const auto& [ev2, t2] : *other) {
            const EventInfo e2 = info_of(m, ev2);
            if (e2.type != 'e' && t2 == states[i] && e2.bot != me.bot) task_finished[i] = ev2;
          }
        }
      } else if (me.type == 'f') {
        task_finished[i] = event;
      }
    }
  }
  x.next.resize(x.n);
  for (std::size_t i = 0; i < x.n; ++i) {
    const auto* edges = edges_of(i);
    if (!edges) continue;
    for (const auto& [event, target] : *edges) {
      const std::size_t j = index.at(target);
      if (j == i) continue;  // A - diag(diag(A))
      const EventInfo me = info_of(m, event);
      const double base = m.fsm.events.at(event).controllable ? start_distance(me) : 0.0;
      double c = base;
      if (!task_finished[i].empty()) {
        const double subtracted = base - start_distance(info_of(m, task_finished[i]));
        c = subtracted > 0 ? subtracted : 0.0;
      }
      const auto key = std::make_pair(i, j);
      if (!x.cost.count(key)) x.next[i].push_back(j);
      x.cost[key] = c;
      x.bot[key] = me.bot;
      x.event[key] = event;
    }
  }
  for (auto& v : x.next) std::sort(v.begin(), v.end());
  return x;
}

}  // namespace

sm::Plan thesis_plan(const sm::Mission& m, const sm::PlanQuery& q) {
  std::map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < m.fsm.states.size(); ++i) index.emplace(m.fsm.states[i], i);
  const Matrices x = calculate_costs(m, q, index);
  const std::size_t n = x.n;
  const std::size_t robots = m.robots.size();
  bool all_positive = true;
  for (const auto& [key, c] : x.cost) all_positive = all_positive && c > 0;
  const double none = all_positive ? 0.0 : kNaN;
  auto is_none = [&](double v) { return all_positive ? v == 0.0 : std::isnan(v); };

  std::vector<double> tbl(n, none), min_cost(n, std::numeric_limits<double>::infinity());
  std::vector<char> settled(n, 0);
  std::vector<std::vector<std::size_t>> path(n);
  std::vector<std::vector<double>> tb(n, std::vector<double>(robots, 0.0));
  std::size_t I = index.at(q.from);
  min_cost[I] = 0;
  tbl[I] = 0;
  settled[I] = 1;
  path[I] = {I};
  std::vector<std::size_t> fid;
  for (const auto& s : m.marked_states) fid.push_back(index.at(s));
  auto any_unsettled = [&] {
    for (const auto f : fid)
      if (!settled[f]) return true;
    return false;
  };
  while (any_unsettled()) {
    const std::vector<double> tab = tbl;
    tbl[I] = none;
    for (const std::size_t J : x.next[I]) {
      if (settled[J]) continue;
      const auto ij = std::make_pair(I, J);
      double c = x.cost.at(ij);
      if (path[I].size() > 1) {
        const std::size_t prev = path[I][path[I].size() - 2];
        const std::size_t b_prev = x.bot.at({prev, I});
        const std::size_t b = x.bot.at(ij);
        if (b_prev != b) c = c + tb[I][b] - tb[I][b_prev];
      }
      if (is_none(tab[J]) || tab[J] > tab[I] + c) {
        tbl[J] = tab[I] + c;
        tb[J] = tb[I];
        tb[J][x.bot.at(ij)] = tb[I][x.bot.at(ij)] + x.cost.at(ij);
        path[J] = path[I];
        path[J].push_back(J);
      } else {
        tbl[J] = tab[J];
        tb[J] = tb[I];
      }
    }
    std::size_t best = n;
    for (std::size_t k = 0; k < n; ++k)
      if (!is_none(tbl[k]) && (best == n || tbl[k] < tbl[best])) best = k;
    if (best == n) break;
    I = best;
    min_cost[I] = tbl[I];
    settled[I] = 1;
  }
  std::size_t final_state = n;
  for (const auto f : fid)
    if (settled[f] && (final_state == n || min_cost[f] < min_cost[final_state])) final_state = f;
  sm::Plan out;
  if (final_state == n) return out;
  std::vector<std::string> events;
  const auto& p = path[final_state];
  for (std::size_t k = 1; k < p.size(); ++k) events.push_back(x.event.at({p[k - 1], p[k]}));
  const auto ev = sm::evaluate_path(m, q, events);
  out.found = true;
  out.events = events;
  out.final_state = ev.final_state;
  out.cost = ev.cost;
  return out;
}

}  // namespace swarmcheck::model::mission
