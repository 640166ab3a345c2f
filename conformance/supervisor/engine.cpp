#include "conformance/supervisor/engine.hpp"

#include "model/supervisor/control.hpp"
#include "model/supervisor/observation.hpp"
#include "model/supervisor/operations.hpp"

namespace swarmcheck::conformance::supervisor {

namespace {

namespace lib = swarmcheck::supervisor;
namespace model = swarmcheck::model::supervisor;

lib::CheckReport model_check(const Automaton& a) {
  lib::CheckReport r;
  r.blocking_states = model::blocking_states(a);
  const auto ac = model::accessible_states(a);
  for (const auto& q : a.states)
    if (!ac.count(q)) r.unreachable_states.push_back(q);
  r.coaccessible = model::coaccessible_states(a).size() == a.states.size();
  return r;
}

}  // namespace

Engine engine_named(const std::string& name) {
  if (name == "impl") return Engine::impl;
  if (name == "model") return Engine::model;
  throw InputError("--engine", "expected impl or model, got \"" + name + "\"");
}

lib::CheckReport check(const Automaton& a, Engine engine) {
  return engine == Engine::model ? model_check(a) : lib::check(a);
}

bool is_nonblocking(const Automaton& a, Engine engine) {
  return engine == Engine::model ? model::is_nonblocking(a) : lib::is_nonblocking(a);
}

Automaton product(const std::vector<Automaton>& parts, const std::vector<std::string>& names,
                  Engine engine, std::uint64_t max_bytes) {
  return engine == Engine::model ? model::product(parts, names) : lib::product(parts, names, max_bytes);
}

bool is_controllable(const Automaton& plant, const Automaton& spec, Engine engine) {
  return engine == Engine::model ? model::is_controllable(plant, spec)
                                 : lib::is_controllable(plant, spec);
}

lib::ControlReport control_report(const Automaton& plant, const Automaton& sup, Engine engine) {
  return engine == Engine::model ? model::control_report(plant, sup) : lib::control_report(plant, sup);
}

Automaton supcon(const Automaton& plant, const Automaton& spec, Engine engine, std::uint64_t max_bytes) {
  return engine == Engine::model ? model::supcon(plant, spec) : lib::supcon(plant, spec, max_bytes);
}

Automaton observer(const Automaton& a, Engine engine, std::uint64_t max_bytes) {
  return engine == Engine::model ? model::observer(a) : lib::observer(a, max_bytes);
}

lib::ObservabilityReport observability(const Automaton& plant, const Automaton& spec, Engine engine) {
  return engine == Engine::model ? model::observability(plant, spec) : lib::observability(plant, spec);
}

Automaton supcon_normal(const Automaton& plant, const Automaton& spec, Engine engine, std::uint64_t max_bytes) {
  return engine == Engine::model ? model::supcon_normal(plant, spec) : lib::supcon_normal(plant, spec, max_bytes);
}

lib::Inclusion language_inclusion(const Automaton& a, const Automaton& b, Engine engine) {
  return engine == Engine::model ? model::language_inclusion(a, b) : lib::language_inclusion(a, b);
}

}  // namespace swarmcheck::conformance::supervisor
