#pragma once
// Keyed counter-based randomness (DESIGN.md A3). A draw is a pure function of
// (seed, tick, robot, purpose): no hidden stream, so the order in which robots or threads
// evaluate never changes a result, and a parallel implementation draws the same numbers.
#include <cstdint>

namespace swarmcheck::exploration {

// SplitMix64's finaliser (Steele, Lea, Flood 2014): a bijection with good avalanche.
constexpr uint64_t splitmix64(uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

enum class Purpose : uint64_t { tie_break = 1, fallback = 2 };

constexpr uint64_t rng_key(uint64_t seed, int64_t tick, int32_t robot, Purpose purpose) {
  uint64_t h = splitmix64(seed);
  h = splitmix64(h ^ static_cast<uint64_t>(tick));
  h = splitmix64(h ^ static_cast<uint64_t>(robot));
  return splitmix64(h ^ static_cast<uint64_t>(purpose));
}

// A uniform index in [0, n) from a key: the high 32 bits scaled by n (Lemire's multiply-shift).
// n <= 2^32; the bias is below n / 2^32, far under anything a run can observe.
constexpr uint32_t uniform_index(uint64_t key, uint32_t n) {
  return static_cast<uint32_t>(((key >> 32) * static_cast<uint64_t>(n)) >> 32);
}

}  // namespace swarmcheck::exploration
