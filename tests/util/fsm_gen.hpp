#pragma once
// Large UMDES .fsm inputs for tests, written as bench/supervisor/gen_fsm.py writes them (the same
// families, the writer's canonical form): chains, counters, Wonham's transfer line, an automaton
// whose observer is exponential.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace swarmcheck::testing::fsm_gen {

struct State {
  std::string name;
  bool marked;
  std::vector<std::pair<std::string, std::string>> edges;   // event, target
};

// events: name -> "c uo"-style attributes ("c\to", "uc\tuo", ...).
inline std::string fsm_text(const std::vector<State>& states, const std::map<std::string, std::string>& attributes) {
  std::string out = std::to_string(states.size()) + "\n\n";
  for (const auto& s : states) {
    out += s.name + "\t" + (s.marked ? "1" : "0") + "\t" + std::to_string(s.edges.size()) + "\n";
    for (const auto& [e, t] : s.edges) out += e + "\t" + t + "\t" + attributes.at(e) + "\n";
    out += "\n";
  }
  return out;
}

inline std::string write(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

// s0 -e-> s1 -e-> ... s(n-1), the last one marked.
inline std::string chain(int n, const std::string& event = "a", const std::string& attributes = "c\to") {
  std::vector<State> s;
  for (int i = 0; i < n; ++i)
    s.push_back({"s" + std::to_string(i), i == n - 1, i + 1 < n ? std::vector<std::pair<std::string, std::string>>{{event, "s" + std::to_string(i + 1)}}
                                                                 : std::vector<std::pair<std::string, std::string>>{}});
  return fsm_text(s, {{event, attributes}});
}

// A cycle of n states counting `event`, state 0 marked: two counters on different events have an
// n x m product.
inline std::string counter(int n, const std::string& event, const std::string& attributes = "c\to") {
  std::vector<State> s;
  for (int i = 0; i < n; ++i) s.push_back({"q" + std::to_string(i), i == 0, {{event, "q" + std::to_string((i + 1) % n)}}});
  return fsm_text(s, {{event, attributes}});
}

// Wonham's transfer line in `folder`: plants M1 M2 TU, specifications B1 B2 (buffers of `slots`
// slots). Returns {plants, specs}.
inline std::pair<std::vector<std::string>, std::vector<std::string>> transfer_line(int slots, const std::filesystem::path& folder) {
  std::filesystem::create_directories(folder);
  const std::map<std::string, std::string> c{{"start1", "c\to"}, {"finish1", "uc\to"}, {"start2", "c\to"}, {"finish2", "uc\to"},
                                             {"start3", "c\to"}, {"pass", "uc\to"},    {"reject", "uc\to"}};
  const auto machine = [&](const std::string& start, const std::vector<std::string>& finishes) {
    std::vector<std::pair<std::string, std::string>> back;
    for (const auto& f : finishes) back.emplace_back(f, "idle");
    return fsm_text({{"idle", true, {{start, "work"}}}, {"work", false, back}}, c);
  };
  const auto buffer = [&](const std::vector<std::string>& fill, const std::string& drain) {
    std::vector<State> s;
    for (int k = 0; k <= slots; ++k) {
      State st{"b" + std::to_string(k), k == 0, {}};
      if (k < slots)
        for (const auto& e : fill) st.edges.emplace_back(e, "b" + std::to_string(k + 1));
      if (k > 0) st.edges.emplace_back(drain, "b" + std::to_string(k - 1));
      std::sort(st.edges.begin(), st.edges.end());
      s.push_back(st);
    }
    return fsm_text(s, c);
  };
  const std::vector<std::string> plants{write(folder / "M1.fsm", machine("start1", {"finish1"})),
                                        write(folder / "M2.fsm", machine("start2", {"finish2"})),
                                        write(folder / "TU.fsm", machine("start3", {"pass", "reject"}))};
  const std::vector<std::string> specs{write(folder / "B1.fsm", buffer({"finish1", "reject"}, "start2")),
                                       write(folder / "B2.fsm", buffer({"finish2"}, "start3"))};
  return {plants, specs};
}

// n + 2 states whose observer has 2^n classes: from 0, an unobservable u guesses that the a just
// coming is the n-th last observed event (the classic blow-up of determinising).
inline std::string exponential_observer(int n) {
  std::string t = std::to_string(n + 2) + "\n\n0 1 3\na 0 c o\nb 0 c o\nu g uc uo\n\ng 1 1\na 1 c o\n";
  for (int i = 1; i < n; ++i)
    t += "\n" + std::to_string(i) + " 1 2\na " + std::to_string(i + 1) + " c o\nb " + std::to_string(i + 1) + " c o\n";
  return t + "\n" + std::to_string(n) + " 1 0\n";
}

}  // namespace swarmcheck::testing::fsm_gen
