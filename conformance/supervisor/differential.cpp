#include "conformance/supervisor/differential.hpp"

#include <deque>
#include <filesystem>
#include <map>

#include "impl/supervisor/fsm_io.hpp"
#include "impl/supervisor/operations.hpp"
#include "model/supervisor/operations.hpp"

namespace swarmcheck::conformance::supervisor {

namespace impl = swarmcheck::impl::supervisor;
namespace model = swarmcheck::model::supervisor;
using spec::supervisor::State;
using spec::supervisor::StateSet;

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
  if (auto d = differ("trim", impl::write_fsm(impl::decompile(impl::trim(f))),
                      impl::write_fsm(model::trim(a))))
    return d;
  return differ("accessible part", impl::write_fsm(impl::decompile(impl::accessible_part(f))),
                impl::write_fsm(model::accessible_part(a)));
}

std::optional<std::string> diff_product(const Automaton& a, const Automaton& b) {
  const impl::Fsm fa = impl::compile(a), fb = impl::compile(b);
  const auto ip = impl::decompile(impl::product({&fa, &fb}, {"a", "b"}));
  const auto mp = model::product({a, b}, {"a", "b"});
  return differ("product", canonical(ip), canonical(mp));
}

std::optional<std::string> diff_synthesis(const Automaton& plant, const Automaton& spec) {
  const impl::Fsm g = impl::compile(plant), s = impl::compile(spec);
  const bool ic = impl::is_controllable(g, s), mc = model::is_controllable(plant, spec);
  if (ic != mc)
    return std::string("controllability differs: impl ") + (ic ? "true" : "false") +
           ", model " + (mc ? "true" : "false");
  return differ("supervisor", canonical(impl::decompile(impl::supcon(g, s))),
                canonical(model::supcon(plant, spec)));
}

std::vector<std::string> write_counterexample(const std::string& dir, const std::string& stem,
                                              const std::vector<Automaton>& automata) {
  std::filesystem::create_directories(dir);
  std::vector<std::string> paths;
  for (std::size_t i = 0; i < automata.size(); ++i) {
    const std::string path = dir + "/" + stem + "_" + std::to_string(i) + ".fsm";
    impl::write_file_atomically(path, impl::write_fsm(automata[i]));
    paths.push_back(path);
  }
  return paths;
}

}  // namespace swarmcheck::conformance::supervisor
