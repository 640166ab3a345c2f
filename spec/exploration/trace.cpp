#include "spec/exploration/trace.hpp"

#include <bit>

namespace swarmcheck::exploration {

json_io::Json trace_header(const Scenario& s) {
  json_io::Json h = json_io::Json::object();
  h["format"] = "swarmcheck-trace";
  h["format_version"] = kTraceFormatVersion;
  h["tool_version"] = kToolVersion;
  h["system"] = "exploration";
  h["scenario"] = json_io::to_json(s);
  h["seed"] = s.seed;
  h["rule"] = json_io::enum_to_string(s.rule);
  h["mode"] = json_io::enum_to_string(s.mode);
  return h;
}

std::string trace_line(const StepRecord& r) { return json_io::to_json(r).dump(); }

void Fnv1a::add(double v) {
  uint64_t bits = std::bit_cast<uint64_t>(v);
  for (int k = 0; k < 8; ++k) {
    h ^= bits & 0xffU;
    h *= 0x100000001b3ULL;
    bits >>= 8;
  }
}

}  // namespace swarmcheck::exploration
