// The public API's operations on Automaton values (swarmcheck/supervisor.hpp): each compiles its
// inputs to the CSR form, runs the fast operation (operations.hpp) and gives a value back; and
// the atomic .fsm file writer. (The reader and writer of the text are fsm_read.cpp and
// fsm_write.cpp, which the fuzz target builds alone.)
#include "impl/io/atomic_file.hpp"
#include "impl/supervisor/operations.hpp"
#include "swarmcheck/supervisor.hpp"

namespace swarmcheck::supervisor {

namespace is = swarmcheck::impl::supervisor;

void write_fsm_file(const std::string& path, const Automaton& a) {
  impl::io::write_file_atomically(path, write_fsm(a));
}

CheckReport check(const Automaton& a) { return is::check(is::compile(a)); }

bool is_nonblocking(const Automaton& a) { return is::is_nonblocking(is::compile(a)); }

Automaton accessible_part(const Automaton& a) {
  return is::decompile(is::accessible_part(is::compile(a)));
}

Automaton trim(const Automaton& a) { return is::decompile(is::trim(is::compile(a))); }

Automaton product(const std::vector<Automaton>& parts, const std::vector<std::string>& names,
                  std::uint64_t max_bytes) {
  if (parts.empty()) throw InputError("product", "expected at least one automaton");
  std::vector<std::string> named = names;
  for (std::size_t i = named.size(); i < parts.size(); ++i)
    named.push_back("part " + std::to_string(i + 1));
  std::vector<is::Fsm> compiled;
  compiled.reserve(parts.size());
  for (const auto& a : parts) compiled.push_back(is::compile(a));
  std::vector<const is::Fsm*> ptrs;
  for (const auto& f : compiled) ptrs.push_back(&f);
  return is::decompile(is::product(ptrs, named, max_bytes));
}

bool is_controllable(const Automaton& plant, const Automaton& spec) {
  return is::is_controllable(is::compile(plant), is::compile(spec));
}

ControlReport control_report(const Automaton& plant, const Automaton& sup) {
  return is::control_report(is::compile(plant), is::compile(sup));
}

Automaton supcon(const Automaton& plant, const Automaton& spec, std::uint64_t max_bytes) {
  return is::decompile(is::supcon(is::compile(plant), is::compile(spec), max_bytes));
}

Automaton observer(const Automaton& a, std::uint64_t max_bytes) {
  return is::decompile(is::observer(is::compile(a), max_bytes));
}

ObservabilityReport observability(const Automaton& plant, const Automaton& spec) {
  return is::observability(is::compile(plant), is::compile(spec));
}

Automaton supcon_normal(const Automaton& plant, const Automaton& spec, std::uint64_t max_bytes) {
  return is::decompile(is::supcon_normal(is::compile(plant), is::compile(spec), max_bytes));
}

Inclusion language_inclusion(const Automaton& a, const Automaton& b) {
  return is::language_inclusion(is::compile(a), is::compile(b));
}

}  // namespace swarmcheck::supervisor
