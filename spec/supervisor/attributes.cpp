#include "spec/supervisor/attributes.hpp"

#include "spec/util/input_error.hpp"

namespace swarmcheck::supervisor {

namespace {

// Pools one attribute: the first statement wins; a different later one is the error.
void pool(const Event& e, const std::optional<Stated>& s, std::optional<Stated>& into,
          const char* yes, const char* no) {
  if (!s) return;
  if (!into) {
    into = s;
    return;
  }
  if (into->value != s->value)
    throw InputError(s->where, "event '" + e + "' is " + (s->value ? yes : no) + " here but " +
                                   (into->value ? yes : no) + " at " + into->where);
}

}  // namespace

std::map<Event, EventAttr> resolve_attributes(const std::vector<Statements>& files) {
  Statements pooled;
  for (const auto& file : files)
    for (const auto& [e, st] : file) {
      EventStatements& p = pooled[e];
      pool(e, st.controllable, p.controllable, "c", "uc");
      pool(e, st.observable, p.observable, "o", "uo");
    }
  std::map<Event, EventAttr> out;
  for (const auto& [e, p] : pooled)
    out[e] = EventAttr{p.controllable ? p.controllable->value : true,
                       p.observable ? p.observable->value : true};
  return out;
}

Automaton with_attributes(Automaton a, const std::map<Event, EventAttr>& attrs) {
  for (auto& [e, attr] : a.events) {
    const auto hit = attrs.find(e);
    if (hit != attrs.end()) attr = hit->second;
  }
  return a;
}

}  // namespace swarmcheck::supervisor
