#include "conformance/supervisor/differential.hpp"

#include <deque>
#include <map>

#include "impl/supervisor/fsm_io.hpp"
#include "impl/supervisor/operations.hpp"
#include "model/supervisor/control.hpp"
#include "model/supervisor/observation.hpp"
#include "model/supervisor/operations.hpp"

namespace swarmcheck::conformance::supervisor {

namespace impl = swarmcheck::impl::supervisor;
namespace model = swarmcheck::model::supervisor;
using swarmcheck::supervisor::State;
using swarmcheck::supervisor::StateSet;

std::string canonical(const Automaton& a) {
  Automaton c;
  c.events = a.events;
  if (!a.states.empty()) {
    std::map<State, std::string> name;
    std::deque<State> queue{a.states.front()};
    name.emplace(a.states.front(), "0");
    while (!queue.empty()) {
      const State q = queue.front();
      queue.pop_front();
      c.states.push_back(name.at(q));
      if (a.marked.count(q)) c.marked.insert(name.at(q));
      const auto row = a.delta.find(q);
      if (row == a.delta.end()) continue;
      for (const auto& [e, t] : row->second) {  // event-name order
        const auto [it, fresh] = name.emplace(t, std::to_string(name.size()));
        if (fresh) queue.push_back(t);
        c.delta[name.at(q)][e] = it->second;
      }
    }
  }
  return impl::write_fsm(c);
}

namespace {

std::vector<State> names_of(const impl::Fsm& f, const std::vector<std::uint8_t>& mask) {
  std::vector<State> out;
  for (impl::StateId s = 0; s < f.state_count(); ++s)
    if (mask[s]) out.push_back(f.state_names[s]);
  return out;
}

std::vector<State> in_order(const Automaton& a, const StateSet& set) {
  std::vector<State> out;
  for (const auto& q : a.states)
    if (set.count(q)) out.push_back(q);
  return out;
}

std::string listed(const std::vector<State>& v) {
  std::string out = "{";
  for (const auto& q : v) out += (out.size() > 1 ? ", " : "") + q;
  return out + "}";
}

std::optional<std::string> differ(const std::string& what, const std::string& impl_text,
                                  const std::string& model_text) {
  if (impl_text == model_text) return std::nullopt;
  return what + " differs:\n--- impl\n" + impl_text + "\n--- model\n" + model_text;
}

}  // namespace

std::optional<std::string> diff_exact(const std::string& what, const impl::Fsm& f, const Automaton& m) {
  if (f.state_count() != m.states.size())
    return what + ": impl has " + std::to_string(f.state_count()) + " states, model " + std::to_string(m.states.size());
  std::map<std::string, std::size_t> first;
  for (std::size_t i = 0; i < f.state_names.size(); ++i) {
    const auto [it, fresh] = first.emplace(f.state_names[i], i);
    if (!fresh)
      return what + ": impl names states " + std::to_string(it->second) + " and " + std::to_string(i) + " both \"" +
             f.state_names[i] + "\" (a duplicate state)";
  }
  for (std::size_t i = 0; i < m.states.size(); ++i)
    if (f.state_names[i] != m.states[i])
      return what + ": state " + std::to_string(i) + " is \"" + f.state_names[i] + "\" in impl, \"" + m.states[i] +
             "\" in the model";
  return differ(what + " (.fsm bytes)", impl::write_fsm(impl::decompile(f)), impl::write_fsm(m));
}

std::optional<std::string> diff_unary(const Automaton& a) {
  const impl::Fsm f = impl::compile(a);
  if (auto d = differ("accessible states", listed(names_of(f, impl::accessible_mask(f))),
                      listed(in_order(a, model::accessible_states(a)))))
    return d;
  if (auto d = differ("coaccessible states", listed(names_of(f, impl::coaccessible_mask(f))),
                      listed(in_order(a, model::coaccessible_states(a)))))
    return d;
  std::vector<State> blocking;
  for (const auto s : impl::blocking_states(f)) blocking.push_back(f.state_names[s]);
  if (auto d = differ("blocking states", listed(blocking), listed(model::blocking_states(a))))
    return d;
  if (impl::is_nonblocking(f) != model::is_nonblocking(a)) return "nonblocking differs";
  if (auto d = diff_exact("trim", impl::trim(f), model::trim(a))) return d;
  return diff_exact("accessible part", impl::accessible_part(f), model::accessible_part(a));
}

namespace {

// Both sides' products of the parts (named "part 1", ... in messages).
std::pair<impl::Fsm, Automaton> both_products(const std::vector<Automaton>& parts) {
  if (parts.size() == 1) return {impl::compile(parts[0]), parts[0]};   // a plant of one component
  std::vector<impl::Fsm> compiled;
  std::vector<std::string> names;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    compiled.push_back(impl::compile(parts[i]));
    names.push_back("part " + std::to_string(i + 1));
  }
  std::vector<const impl::Fsm*> ptrs;
  for (const auto& c : compiled) ptrs.push_back(&c);
  return {impl::product(ptrs, names), model::product(parts, names)};
}

}  // namespace

std::optional<std::string> diff_product(const std::vector<Automaton>& parts, BuiltSizes* sizes) {
  const auto [ip, mp] = both_products(parts);
  if (sizes) sizes->product_states = mp.states.size();
  return diff_exact("product", ip, mp);
}

std::optional<std::string> diff_synthesis(const std::vector<Automaton>& plant_parts, const Automaton& spec,
                                          BuiltSizes* sizes) {
  const auto [ig, mg] = both_products(plant_parts);
  const impl::Fsm s = impl::compile(spec);
  const bool ic = impl::is_controllable(ig, s), mc = model::is_controllable(mg, spec);
  if (ic != mc)
    return std::string("controllability differs: impl ") + (ic ? "true" : "false") + ", model " + (mc ? "true" : "false");
  const Automaton msup = model::supcon(mg, spec);
  if (sizes) *sizes = BuiltSizes{mg.states.size(), msup.states.size()};
  return diff_exact("supervisor", impl::supcon(ig, s), msup);
}

namespace {

std::string words(const std::vector<std::string>& w) {
  std::string out = "[";
  for (const auto& e : w) out += (out.size() > 1 ? " " : "") + e;
  return out + "]";
}

std::string shown(const swarmcheck::supervisor::Inclusion& i) {
  return std::string("closed ") + (i.closed ? "yes" : "no") + " " + words(i.closed_witness) +
         ", marked " + (i.marked ? "yes" : "no") + " " + words(i.marked_witness);
}

}  // namespace

std::optional<std::string> diff_control(const std::vector<Automaton>& plant_parts, const Automaton& sup) {
  const auto [ig, mg] = both_products(plant_parts);
  const auto ir = impl::control_report(ig, impl::compile(sup));
  const auto mr = model::control_report(mg, sup);
  auto shown_report = [](const swarmcheck::supervisor::ControlReport& r) {
    return std::to_string(r.closed_loop_states) + " states, controllable " + (r.controllable ? "yes" : "no") +
           " " + words(r.witness) + " " + r.disabled_event + ", nonblocking " + (r.nonblocking ? "yes" : "no") +
           " " + words(r.blocking_witness);
  };
  return differ("control report", shown_report(ir), shown_report(mr));
}

std::optional<std::string> diff_observer(const Automaton& a) {
  return diff_exact("observer", impl::observer(impl::compile(a)), model::observer(a));
}

std::optional<std::string> diff_observability(const std::vector<Automaton>& plant_parts, const Automaton& spec) {
  const auto [ig, mg] = both_products(plant_parts);
  const auto ir = impl::observability(ig, impl::compile(spec));
  const auto mr = model::observability(mg, spec);
  auto shown_report = [](const swarmcheck::supervisor::ObservabilityReport& r) {
    return std::string("observable ") + (r.observable ? "yes" : "no") + " " + words(r.word) + " " +
           words(r.twin) + " " + r.event;
  };
  return differ("observability", shown_report(ir), shown_report(mr));
}

std::optional<std::string> diff_supcon_normal(const std::vector<Automaton>& plant_parts, const Automaton& spec,
                                              BuiltSizes* sizes) {
  const auto [ig, mg] = both_products(plant_parts);
  const Automaton msup = model::supcon_normal(mg, spec);
  if (sizes) *sizes = BuiltSizes{mg.states.size(), msup.states.size()};
  return diff_exact("normal supervisor", impl::supcon_normal(ig, impl::compile(spec)), msup);
}

std::optional<std::string> diff_inclusion(const Automaton& a, const Automaton& b) {
  const auto ii = impl::language_inclusion(impl::compile(a), impl::compile(b));
  const auto mi = model::language_inclusion(a, b);
  return differ("language inclusion", shown(ii), shown(mi));
}

}  // namespace swarmcheck::conformance::supervisor
