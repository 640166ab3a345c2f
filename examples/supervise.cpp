// A program using the swarmcheck automata library: check the thesis's supervisor, synthesise one
// from the component automata, and compare the two languages.
//   supervise CONTROL2.fsm COMPONENTS_DIR
#include <cstdio>
#include <string>
#include <swarmcheck/supervisor.hpp>

namespace sv = swarmcheck::supervisor;

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: supervise CONTROL2.fsm COMPONENTS_DIR\n");
    return 2;
  }
  try {
    const sv::Automaton control2 = sv::read_fsm_file(argv[1]);
    const sv::CheckReport report = sv::check(control2);
    std::printf("%s: %zu states, nonblocking: %s\n", argv[1], control2.states.size(),
                report.nonblocking() ? "yes" : "no");
    const std::string dir = std::string(argv[2]) + "/";
    auto read_all = [&](std::initializer_list<const char*> names) {
      std::vector<sv::Automaton> parts;
      for (const char* n : names) parts.push_back(sv::read_fsm_file(dir + n));
      return sv::product(parts);
    };
    const sv::Automaton plant = read_all({"region_a.fsm", "tasks_a.fsm", "region_b.fsm", "tasks_b.fsm"});
    const sv::Automaton spec = read_all({"avoidance.fsm", "located.fsm", "completion.fsm"});
    const sv::Automaton sup = sv::supcon(plant, spec);
    std::printf("supervisor: %zu states (plant %zu), nonblocking: %s\n", sup.states.size(),
                plant.states.size(), sv::check(sup).nonblocking() ? "yes" : "no");
    const sv::Inclusion in = sv::language_inclusion(sup, control2);
    std::string witness;
    for (const auto& e : in.closed_witness) witness += " " + e;
    std::printf("L(supervisor) in L(control2): %s%s%s\n", in.closed ? "yes" : "no",
                in.closed ? "" : ", witness:", witness.c_str());
    return report.nonblocking() && !sup.states.empty() ? 0 : 1;
  } catch (const swarmcheck::InputError& e) {
    std::fprintf(stderr, "supervise: %s\n", e.what());
    return 2;
  }
}
