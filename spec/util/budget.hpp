#pragma once
// Resource budgets: work whose size is known (or estimated) before it is allocated is refused
// when it would not fit, with the estimate, the limit and the flag that raises it, instead of
// dying in std::bad_alloc or taking the machine's memory. Refusal is bad input (exit status 2).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "spec/util/input_error.hpp"

namespace swarmcheck {

// "1.5 GiB", "640 MiB", "12 KiB", "100 B".
inline std::string format_bytes(double bytes) {
  const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB"};
  int u = 0;
  while (bytes >= 1024.0 && u < 5) {
    bytes /= 1024.0;
    ++u;
  }
  char text[32];
  std::snprintf(text, sizeof text, u == 0 ? "%.0f %s" : "%.1f %s", bytes, units[u]);
  return text;
}

// A value for a size flag that is at least `bytes`, in whole units: "97G", "640M", "1M".
inline std::string size_flag_value_at_least(double bytes) {
  constexpr double kMiB = 1024.0 * 1024.0, kGiB = 1024.0 * kMiB;
  if (!(bytes <= 1.8e19)) return "0";   // beyond what a size flag takes: no limit at all
  if (bytes > kGiB) return std::to_string(static_cast<std::uint64_t>(std::ceil(bytes / kGiB))) + "G";
  return std::to_string(std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::ceil(bytes / kMiB)))) + "M";
}

// A limit refused: "<what> needs about <estimate>, over the <flag> limit of <limit> (raise it
// with <flag> ...)". `where`: the input or option the size comes from.
class BudgetExceeded : public InputError {
 public:
  BudgetExceeded(const std::string& where, const std::string& what, double estimate_bytes,
                 double limit_bytes, const std::string& flag)
      : InputError(where, what + " needs about " + format_bytes(estimate_bytes) + ", over the limit of " +
                              format_bytes(limit_bytes) + " (raise it with " + flag + ", e.g. " + flag +
                              " " + size_flag_value_at_least(estimate_bytes) + ", or make the input smaller)") {}
  BudgetExceeded(const std::string& where, const std::string& message) : InputError(where, message) {}
};

// The limits one command works within.
struct Budgets {
  std::uint64_t memory_bytes = 0;      // 0: no limit (library callers); the CLI sets its default
  std::uint64_t trace_bytes = 0;       // 0: no limit
};

inline void require_within(const std::string& where, const std::string& what, double estimate_bytes,
                           std::uint64_t limit_bytes, const std::string& flag) {
  if (limit_bytes != 0 && estimate_bytes > static_cast<double>(limit_bytes))
    throw BudgetExceeded(where, what, estimate_bytes, static_cast<double>(limit_bytes), flag);
}

}  // namespace swarmcheck
