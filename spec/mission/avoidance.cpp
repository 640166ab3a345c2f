// The region-entry rule of execution.
#include "spec/mission/avoidance.hpp"

namespace swarmcheck::mission {

std::vector<std::string> entry_events(const Mission& m, std::size_t robot, const Point& from,
                                      const Point& to) {
  std::vector<std::string> out;
  for (std::size_t g = 0; g < m.regions.size(); ++g)
    if (!inside(m.regions[g], from) && inside(m.regions[g], to))
      if (const auto* e = event_for(m, MeaningKind::region_entry, robot, g)) out.push_back(*e);
  return out;
}

std::optional<std::string> fire_all(const Mission& m, const std::string& q,
                                    const std::vector<std::string>& events) {
  std::string state = q;
  for (const auto& e : events) {
    const auto next = supervisor::successor(m.fsm, state, e);
    if (!next) return std::nullopt;
    state = *next;
  }
  return state;
}

}  // namespace swarmcheck::mission
