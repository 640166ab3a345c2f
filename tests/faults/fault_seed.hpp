#pragma once
// What every fault test of the catalogue shares: the fault it carries (one generated line per
// fault, tests/faults/CMakeLists.txt, so that each test source is compiled once per subsystem),
// what the campaign must see, the seed it runs under, and the campaign's time limit for a case.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <string>

extern const char* const kFaultName;
extern const char* const kFaultExpect;   // "difference", "crash" or "hang" (the fault file's expect:)

namespace swarmcheck::testing::faults {

// SWARMCHECK_FAULT_SEED (ctest sets 1, 2 and 3), else 1: the campaign's one seed.
inline uint64_t seed() {
  const char* s = std::getenv("SWARMCHECK_FAULT_SEED");
  return s && *s ? std::strtoull(s, nullptr, 10) : 1;
}

inline bool expects(const char* kind) { return std::string(kFaultExpect) == kind; }

// A hang is found when a case shows no progress for the limit, and each candidate that hangs
// while shrinking costs it again: 2 s (a step of the campaigns' cases takes well under a
// millisecond) where the fault hangs, the campaigns' default elsewhere.
inline std::chrono::milliseconds quiet_limit() {
  return expects("hang") ? std::chrono::milliseconds(2000) : std::chrono::milliseconds(std::chrono::seconds(60));
}

// The counterexample's text must show what the fault file expects: a crash or a hang of the
// library, or (by default) a difference, neither a crash nor a hang.
inline void check_expected(const std::string& text) {
  const bool crashed = text.find("impl crashed with") != std::string::npos;
  const bool hung = text.find("impl hung") != std::string::npos;
  if (expects("crash")) {
    EXPECT_TRUE(crashed) << text;
  } else if (expects("hang")) {
    EXPECT_TRUE(hung) << text;
  } else {
    EXPECT_FALSE(crashed || hung) << text;
  }
}

}  // namespace swarmcheck::testing::faults
