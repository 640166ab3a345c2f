#pragma once
// Field records of the exploration trace (trace format version 2; spec/exploration/trace.hpp).
//
// `run --trace-field K` adds, after the step record of every K-th step (step 0 and the last step
// included), one line with the whole grid:
//
//   {"type": "field", "step": S, "map_size": N,
//    "encoding": "float32-le-base64",
//    "pheromone": "<base64 of N*N IEEE-754 binary32, little endian, cell (i, j) at i*N + j>",
//    "visited": "<base64 of N*N bits, cell k at byte k/8, bit k%8 (LSB first)>",
//    "pheromone_max": <the largest exact value, a double>,
//    "digest": <FNV-1a of the exact doubles: equals the step record's pheromone_digest>}
//
// float32 keeps the picture (relative error below 6e-8) at half the size; the exact field stays
// checkable through the digest. The header of such a trace says "format_version": 2 and
// "field_every": K. Readers of version 1 traces need no change: a version 2 trace without
// field lines is not written (version 1 is kept then, byte for byte).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "spec/util/hana_json.hpp"

namespace swarmcheck::exploration {

inline constexpr int kTraceFieldFormatVersion = 2;
inline constexpr const char* kFieldEncoding = "float32-le-base64";

// The grid at one step, exact: pheromone[i*N + j] and visited[i*N + j].
struct FieldSnapshot {
  int64_t step = 0;
  int32_t map_size = 0;
  std::vector<double> pheromone;
  std::vector<bool> visited;
};

// The field line's JSON (see above).
json_io::Json field_record(const FieldSnapshot& f);

// What a reader gets back: the float32 values widened to double, the visited bits, the digest.
struct DecodedField {
  int64_t step = 0;
  int32_t map_size = 0;
  std::vector<float> pheromone;
  std::vector<bool> visited;
  double pheromone_max = 0.0;
  uint64_t digest = 0;
};

// Throws InputError(where, ...) for a malformed field record.
DecodedField decode_field_record(const json_io::Json& j, const std::string& where);

std::string base64_encode(std::string_view bytes);
// Throws InputError(where, ...) on a character outside the alphabet or a bad length.
std::string base64_decode(std::string_view text, const std::string& where);

}  // namespace swarmcheck::exploration
