#pragma once
// How a verb is wired into the `swarmcheck` command line: each verb lives in its own file and
// exposes `void add_<name>_verb(CLI::App& app, int& exit_code)`, which registers a subcommand
// whose callback runs the verb inside guarded() and stores its exit status.
#include <CLI/CLI.hpp>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <memory>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <functional>
#include <new>
#include <string>
#include <string_view>

#include "impl/io/usable_memory.hpp"
#include "spec/util/budget.hpp"
#include "spec/util/input_error.hpp"
#include "spec/util/utf8.hpp"

namespace swarmcheck::cli {

// A message as one short printable line: control bytes and bytes that are not UTF-8 (echoed from
// a user's file) are written as \xNN, and a message over 400 bytes (a long quoted excerpt) is cut
// with a note, so one bad input never floods or garbles the terminal.
inline std::string printable_message(const std::string& text) {
  constexpr std::size_t kMaxBytes = 400;
  std::string out;
  std::size_t k = 0;
  while (k < text.size() && out.size() < kMaxBytes) {
    const auto b = static_cast<unsigned char>(text[k]);
    const std::size_t bad = utf8::first_invalid_byte(std::string_view(text).substr(k, 4));
    if (b < 0x20 || b == 0x7f || bad == 0) {
      char esc[8];
      std::snprintf(esc, sizeof esc, "\\x%02X", b);
      out += esc;
      ++k;
      continue;
    }
    const std::size_t len = b < 0x80 ? 1 : b < 0xE0 ? 2 : b < 0xF0 ? 3 : 4;
    out.append(text, k, len);
    k += len;
  }
  if (k < text.size()) out += " ... (" + std::to_string(text.size() - k) + " more bytes)";
  return out;
}

// --threads N (0: every core), defaulting to the SWARMCHECK_THREADS environment variable. The
// results never depend on it; only the time does.
inline CLI::Option* add_threads_option(CLI::App* cmd, int32_t& threads, const std::string& what) {
  const CLI::Validator count(
      [](std::string& text) -> std::string {
        int32_t v = -1;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
        if (ec == std::errc() && end == text.data() + text.size() && v >= 0 && v <= (1 << 16)) return "";
        return "expected an integer in [0, 65536] (from --threads or SWARMCHECK_THREADS), got '" +
               printable_message(text) + "'";
      },
      "INT in [0, 65536]");
  return cmd->add_option("--threads", threads, what + " (0: every core)")
      ->envname("SWARMCHECK_THREADS")
      ->check(count)
      ->capture_default_str();
}

// Runs a verb body. Bad input (InputError) prints one line and gives exit status 2; any other
// exception is a bug in swarmcheck: it is reported as such with status 3, never a crash.
inline int guarded(const std::function<int()>& body) {
  try {
    return body();
  } catch (const InputError& e) {
    std::fprintf(stderr, "swarmcheck: error: %s\n", printable_message(e.what()).c_str());
    return 2;
  } catch (const std::bad_alloc&) {
    // Budgets refuse what is estimated not to fit; this is what they did not foresee.
    std::fprintf(stderr, "swarmcheck: error: out of memory (lower the input's size, or raise --memory-limit "
                         "if a budget let it through)\n");
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "swarmcheck: internal error (please report): %s\n", printable_message(e.what()).c_str());
    return 3;
  }
}

// A seed is a decimal integer in [0, 2^64 - 1], as written: CLI11 alone would wrap -1 and clamp
// 99999999999999999999 to 2^64 - 1, silently running another seed than the one asked for.
inline CLI::Validator seed_validator() {
  return CLI::Validator(
      [](const std::string& text) -> std::string {
        uint64_t value = 0;
        const char* end = text.data() + text.size();
        const auto [ptr, ec] = std::from_chars(text.data(), end, value);
        if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos || ec != std::errc() || ptr != end)
          return "expected an integer in [0, 18446744073709551615], got " + text;
        return {};
      },
      "SEED");
}

// ---- resource budgets (spec/util/budget.hpp) ----------------------------------------------------

// usable_memory() and default_memory_limit(): impl/io/usable_memory.hpp (the Python package
// refuses what cannot fit with the same limit).
using impl::io::default_memory_limit;
using impl::io::usable_memory;
inline constexpr std::uint64_t kDefaultMaxTraceBytes = std::uint64_t{8} << 30;   // 8 GiB

// "64G", "512M", "1.5G", "2T", "4096" (bytes), with an optional "iB"/"B"; 0 turns a limit off.
inline std::uint64_t parse_size(const std::string& text, const std::string& flag) {
  const std::string expected = "expected a size such as 8G, 512M, 1.5T or a number of bytes (0: no limit), got \"" + text + "\"";
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    throw InputError(flag, expected);
  }
  std::string unit = text.substr(used);
  for (const char* suffix : {"iB", "B"})
    if (unit.size() >= std::char_traits<char>::length(suffix) && unit.ends_with(suffix) && unit != "B") {
      unit.resize(unit.size() - std::char_traits<char>::length(suffix));
      break;
    }
  if (unit == "B") unit.clear();
  double scale = 1;
  if (unit == "K" || unit == "k") scale = 1024.0;
  else if (unit == "M") scale = 1024.0 * 1024;
  else if (unit == "G") scale = 1024.0 * 1024 * 1024;
  else if (unit == "T") scale = 1024.0 * 1024 * 1024 * 1024;
  else if (!unit.empty()) throw InputError(flag, expected);
  if (!(value >= 0) || value * scale > 1.8e19) throw InputError(flag, expected);
  // Under one byte but not 0 would truncate to 0, which turns the limit off: not what was asked.
  if (value > 0 && value * scale < 1) throw InputError(flag, expected);
  return static_cast<std::uint64_t>(value * scale);
}

// parse_size while CLI11 parses: its own error type, so a bad size is a usage error (status 2).
inline std::uint64_t size_option(const std::string& text, const std::string& flag) {
  try {
    return parse_size(text, flag);
  } catch (const InputError& e) {
    throw CLI::ValidationError(e.what());
  }
}

// "30", "30s", "2.5m", "1h": seconds; 0 turns the limit off.
inline double parse_duration(const std::string& text, const std::string& flag) {
  const std::string expected = "expected a duration such as 30, 30s, 5m or 2h (0: no limit), got \"" + text + "\"";
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    throw InputError(flag, expected);
  }
  const std::string unit = text.substr(used);
  const double scale = unit.empty() || unit == "s" ? 1 : unit == "m" ? 60 : unit == "h" ? 3600 : -1;
  if (scale < 0 || !(value >= 0) || !(value * scale <= 1e9)) throw InputError(flag, expected);
  return value * scale;
}

// What the process holds before any work (its code, libraries, the heap's start): the resident
// memory of `swarmcheck fsm check` on a two-state automaton, measured. Every command's memory
// estimate counts it.
inline constexpr double kProcessBytes = 15.0 * (1 << 20);

// The mean of n and the next power of two: the bytes a vector grown to n elements by doubling
// holds at its peak, in elements (its old and new blocks are both resident while it moves).
inline double grown_elements(double n) {
  double p = 1;
  while (p < n) p *= 2;
  return n <= 0 ? 0 : (n + p) / 2;
}

// The peak resident memory of this process so far, bytes (getrusage's ru_maxrss is in KiB).
inline double peak_resident_bytes() {
  struct rusage u {};
  ::getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) * 1024.0;
}

// --memory-report: one line on stderr at the end of the work, the budget's estimate of the peak
// beside the peak measured (what tests/hardening/memory_estimate_test.cpp holds within 1.3x).
inline void report_memory(const Budgets& b, double estimate_bytes) {
  if (!b.report) return;
  std::fprintf(stderr, "swarmcheck: memory: estimated peak %.0f bytes (%s), measured peak resident %.0f bytes (%s)\n",
               estimate_bytes, format_bytes(estimate_bytes).c_str(), peak_resident_bytes(),
               format_bytes(peak_resident_bytes()).c_str());
}

// --memory-limit and --memory-report (and, for verbs that write traces, --max-trace-bytes) on a
// verb; the values are read into `b` when the command line is parsed.
inline void add_budget_options(CLI::App* cmd, Budgets& b, bool trace) {
  b.memory_bytes = default_memory_limit();
  cmd->add_option_function<std::string>(
         "--memory-limit", [&b](const std::string& v) { b.memory_bytes = size_option(v, "--memory-limit"); },
         "Refuse work estimated to need more memory than this (default: 3/4 of physical memory or of "
         "a lower ulimit -v / cgroup limit, "
         "here " + format_bytes(static_cast<double>(b.memory_bytes)) + "; 0: no limit)")
      ->type_name("SIZE");
  cmd->add_flag("--memory-report", b.report,
                "At the end, print on stderr the memory the budget estimated this command needs at its peak, and the peak "
                "measured");
  if (!trace) return;
  b.trace_bytes = kDefaultMaxTraceBytes;
  cmd->add_option_function<std::string>(
         "--max-trace-bytes", [&b](const std::string& v) { b.trace_bytes = size_option(v, "--max-trace-bytes"); },
         "Refuse a trace estimated to be larger than this (default 8G; 0: no limit)")
      ->type_name("SIZE");
}

// --time-limit on a verb whose work can grow exponentially or quadratically with its input (a
// product, an observer, the pairs of an observability check): past it the work stops, exit 2,
// with how far it got.
inline void add_time_limit_option(CLI::App* cmd, Budgets& b) {
  cmd->add_option_function<std::string>(
         "--time-limit", [&b](const std::string& v) {
           try {
             b.time_limit_s = parse_duration(v, "--time-limit");
           } catch (const InputError& e) {
             throw CLI::ValidationError(e.what());
           }
         },
         "Stop the work after this long (30, 30s, 5m, 2h), exit 2 with how far it got (default 0: no limit)")
      ->type_name("DURATION");
}

}  // namespace swarmcheck::cli
