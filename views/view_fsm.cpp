// The automaton view: the state graph laid out by dot, a search box, and the state list.
#include "impl/supervisor/fsm_io.hpp"
#include "views/fsm_svg.hpp"
#include "views/view.hpp"

namespace swarmcheck::views {

inline constexpr std::size_t kListedTransitionsMax = 200'000;

Page fsm_page(const std::string& text, const std::string& path, const std::atomic<bool>* cancel) {
  const swarmcheck::supervisor::Automaton a = impl::supervisor::read_fsm(text, path);
  const std::size_t transitions = swarmcheck::supervisor::transition_count(a);
  json_io::Json states = json_io::Json::array();
  std::size_t listed = 0;
  for (const auto& q : a.states) {
    json_io::Json out = json_io::Json::array();
    const auto row = a.delta.find(q);
    if (row != a.delta.end())
      for (const auto& [e, target] : row->second)
        if (listed++ < kListedTransitionsMax) out.push_back(json_io::Json::array({e, target}));
    states.push_back({{"name", q}, {"marked", a.marked.count(q) != 0}, {"out", out}});
  }
  json_io::Json events = json_io::Json::array();
  for (const auto& [e, attr] : a.events)
    events.push_back({{"name", e}, {"controllable", attr.controllable}, {"observable", attr.observable}});
  json_io::Json data = {{"kind", "fsm"}, {"file", path}, {"states", states}, {"events", events},
                        {"transitions", transitions}, {"listed_transitions", std::min(listed, kListedTransitionsMax)}};
  std::optional<std::string> svg;
  if (transitions <= kLayoutTransitionsMax && (svg = fsm_svg_within(a, kLayoutTimeMax, cancel))) {
    data["svg"] = *svg;
  } else if (transitions <= kLayoutTransitionsMax) {
    data["svg"] = nullptr;
    data["no_layout"] = "dot did not lay out its " + std::to_string(transitions) + " transitions within " +
                        std::to_string(std::chrono::duration_cast<std::chrono::seconds>(kLayoutTimeMax).count()) +
                        " s: search the list";
  } else {
    data["svg"] = nullptr;
    data["no_layout"] = "the automaton has " + std::to_string(transitions) + " transitions, more than the " +
                        std::to_string(kLayoutTransitionsMax) + " that dot lays out in reasonable time: search the list";
  }
  return Page{"swarmcheck automaton: " + path, data};
}

}  // namespace swarmcheck::views
