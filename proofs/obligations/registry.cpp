#include <stdexcept>

#include "proofs/obligations/obligation.hpp"

namespace swarmcheck::proofs {

const char* to_string(Verdict v) {
  switch (v) {
    case Verdict::proved: return "proved";
    case Verdict::refuted: return "refuted";
    default: return "unknown";
  }
}

Verdict verdict_from_string(const std::string& s) {
  if (s == "proved") return Verdict::proved;
  if (s == "refuted") return Verdict::refuted;
  if (s == "unknown") return Verdict::unknown;
  throw std::invalid_argument("not a verdict: " + s);
}

const std::vector<Obligation>& all_obligations() {
  static const std::vector<Obligation> all = [] {
    std::vector<Obligation> v;
    for (auto part : {servo_obligations, atan2_obligations, handshake_obligations, handshake_counter_obligations,
                      handshake_any_robots_obligations, pheromone_obligations, occupancy_obligations,
                      orientation_obligations})
      for (Obligation& o : part()) v.push_back(std::move(o));
    return v;
  }();
  return all;
}

}  // namespace swarmcheck::proofs
