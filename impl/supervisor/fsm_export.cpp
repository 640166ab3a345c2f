#include "impl/supervisor/fsm_export.hpp"

#include <nlohmann/json.hpp>

namespace swarmcheck::supervisor {

namespace {

// A DOT double-quoted string: only '"' and '\' need escaping in our names.
std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

}  // namespace

std::string to_dot(const Automaton& a) {
  std::string out = "digraph fsm {\n  rankdir=LR;\n  node [shape=circle];\n";
  if (!a.states.empty())
    out += "  __start [shape=point];\n  __start -> " + quoted(a.states.front()) + ";\n";
  for (const auto& q : a.states)
    if (a.marked.count(q)) out += "  " + quoted(q) + " [shape=doublecircle];\n";
  for (const auto& q : a.states) {
    const auto row = a.delta.find(q);
    if (row == a.delta.end()) continue;
    for (const auto& [e, target] : row->second) {
      out += "  " + quoted(q) + " -> " + quoted(target) + " [label=" + quoted(e);
      if (!a.events.at(e).controllable) out += ", style=dashed";
      out += "];\n";
    }
  }
  return out + "}\n";
}

std::string to_json_text(const Automaton& a) {
  using Json = nlohmann::ordered_json;
  Json j = Json::object();
  j["initial"] = a.states.empty() ? Json(nullptr) : Json(a.states.front());
  Json states = Json::array();
  for (const auto& q : a.states) {
    Json transitions = Json::array();
    const auto row = a.delta.find(q);
    if (row != a.delta.end())
      for (const auto& [e, target] : row->second)
        transitions.push_back({{"event", e}, {"target", target}});
    states.push_back(
        {{"name", q}, {"marked", a.marked.count(q) != 0}, {"transitions", transitions}});
  }
  j["states"] = states;
  Json events = Json::array();
  for (const auto& [e, attr] : a.events)
    events.push_back(
        {{"name", e}, {"controllable", attr.controllable}, {"observable", attr.observable}});
  j["events"] = events;
  return j.dump(2) + "\n";
}

}  // namespace swarmcheck::supervisor
