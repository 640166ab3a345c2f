#pragma once
// The trace format (DESIGN.md, conformance contract): JSON Lines. Line 1 is the header
// {"format": "swarmcheck-trace", "format_version": 1, "tool_version", "system": "exploration",
//  "scenario": {...}, "seed", "rule", "mode"}; then one StepRecord per line (derived from its
// Hana declaration), from step 0 (the initial state) on. Doubles are written to round-trip.
// Format version 2 (`run --trace-field K`) adds field records: spec/exploration/trace_field.hpp.
#include <string>

#include "spec/exploration/types.hpp"
#include "spec/util/hana_json.hpp"

namespace swarmcheck::exploration {

inline constexpr int kTraceFormatVersion = 1;
inline constexpr const char* kToolVersion = "0.1.0";

json_io::Json trace_header(const Scenario& s);
std::string trace_line(const StepRecord& r);

// FNV-1a (64-bit) over the bit patterns of doubles, fed one at a time.
struct Fnv1a {
  uint64_t h = 0xcbf29ce484222325ULL;
  void add(double v);
};

}  // namespace swarmcheck::exploration
