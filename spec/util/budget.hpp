#pragma once
// Resource budgets: work whose size is known (or estimated) before it is allocated is refused
// when it would not fit, with the estimate, the limit and the flag that raises it, instead of
// dying in std::bad_alloc or taking the machine's memory. Refusal is bad input (exit status 2).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
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


// The limits of a construction whose size shows only as it grows (a product, an observer, the
// pairs of an observability check, normal synthesis): every so often it checks its estimate of
// the memory its command will need at its peak, given what it has found so far, and the clock;
// past either limit it stops with a BudgetExceeded that says how far it got (bad input: exit 2).
// peak_estimate() is the largest estimate checked, what --memory-report prints next to the
// measured peak.
class WorkBudget {
 public:
  using Clock = std::chrono::steady_clock;
  WorkBudget() = default;
  // memory_bytes 0: no memory limit; time_limit_s 0: no time limit (counted from now).
  explicit WorkBudget(std::uint64_t memory_bytes, double time_limit_s = 0)
      : memory_bytes_(memory_bytes), time_limit_s_(time_limit_s) {
    if (time_limit_s > 0)
      deadline_ = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(time_limit_s));
  }
  std::uint64_t memory_bytes() const { return memory_bytes_; }
  double peak_estimate() const { return peak_; }
  // The estimate a finished construction came to: recorded, not checked (the work is done).
  void note(double estimate_bytes) { peak_ = std::max(peak_, estimate_bytes); }

  // `where` names the construction's inputs, `done()` says how far it got ("the product stopped
  // after exploring 4096 states (10000 found)"); called only when a limit stops it.
  // Called at every check, before the limits are: it may throw to stop the construction where a
  // limit would (the Python package raises Ctrl-C's KeyboardInterrupt through it). None by default.
  void set_interrupt(std::function<void()> interrupt) { interrupt_ = std::move(interrupt); }

  template <class Done>
  void check(const std::string& where, double estimate_bytes, const Done& done) {
    if (interrupt_) interrupt_();
    peak_ = std::max(peak_, estimate_bytes);
    if (memory_bytes_ != 0 && estimate_bytes > static_cast<double>(memory_bytes_))
      throw BudgetExceeded(where, done() + ": about " + format_bytes(estimate_bytes) + " and growing, over the limit of " +
                                      format_bytes(static_cast<double>(memory_bytes_)) +
                                      " (raise it with --memory-limit, e.g. --memory-limit " +
                                      size_flag_value_at_least(2.0 * static_cast<double>(memory_bytes_)) + ")");
    if (time_limit_s_ > 0 && Clock::now() > deadline_) {
      char limit[32];
      std::snprintf(limit, sizeof limit, "%g", time_limit_s_);
      char more[32];
      std::snprintf(more, sizeof more, "%g", 4 * time_limit_s_);
      throw BudgetExceeded(where, done() + ": the --time-limit of " + limit + " s is over (raise it with --time-limit, e.g. --time-limit " +
                                      more + ", or 0 for none)");
    }
  }
 private:
  std::uint64_t memory_bytes_ = 0;
  double time_limit_s_ = 0;
  Clock::time_point deadline_ = Clock::time_point::max();
  double peak_ = 0;
  std::function<void()> interrupt_;
};

// The limits one command works within.
struct Budgets {
  std::uint64_t memory_bytes = 0;      // 0: no limit (library callers); the CLI sets its default
  std::uint64_t trace_bytes = 0;       // 0: no limit
  double time_limit_s = 0;             // 0: no limit (the verbs whose work may grow without bound)
  bool report = false;                 // --memory-report: the estimate and the measured peak, at the end
  // The limits of a construction of this command, its clock started now.
  WorkBudget work() const { return WorkBudget(memory_bytes, time_limit_s); }
};

inline void require_within(const std::string& where, const std::string& what, double estimate_bytes,
                           std::uint64_t limit_bytes, const std::string& flag) {
  if (limit_bytes != 0 && estimate_bytes > static_cast<double>(limit_bytes))
    throw BudgetExceeded(where, what, estimate_bytes, static_cast<double>(limit_bytes), flag);
}

}  // namespace swarmcheck
