// libFuzzer target for the exploration trace reader of `swarmcheck replay`
// (conformance/exploration/trace_io.hpp): replay_trace, against the library and against the
// model, on the input written to a file. Any bytes either replay (with or without a divergence)
// or raise one InputError; never another exception, a crash, a hang or a sanitizer report.
//
// Replay re-runs the header's scenario up to the records' steps, so a valid header may ask for
// a 65536 x 65536 map or 2^31 steps: slow by design, not a reader fault. Inputs whose header
// scenario is larger than a small budget (below) are not replayed and are kept out of the corpus.
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>

#include "conformance/exploration/trace_io.hpp"
#include "spec/util/hana_json.hpp"
#include "spec/util/json_text.hpp"
#include "spec/util/input_error.hpp"

namespace {

using Json = swarmcheck::json_io::Json;

// The budget: map side, steps and sensing range of the scenario a replay may simulate.
constexpr std::int64_t kFuzzMapSizeMax = 32;
constexpr std::int64_t kFuzzStepsMax = 400;
constexpr std::int64_t kFuzzRangeMax = 32;

// Absent, not an integer, or at most `max` (an absent or mistyped key is the reader's to refuse).
bool within(const Json& o, const char* key, std::int64_t max, bool absent_ok) {
  const auto it = o.find(key);
  if (it == o.end()) return absent_ok;
  if (it->is_number_unsigned()) return it->get<std::uint64_t>() <= static_cast<std::uint64_t>(max);
  if (it->is_number_integer()) return it->get<std::int64_t>() <= max;
  return true;
}

// Whether replaying the trace whose first line is `header` stays within the budget.
bool small_enough(const std::string& header) {
  Json h;
  try {
    h = swarmcheck::json_io::parse_json_text(header, "trace");
  } catch (const swarmcheck::InputError&) {
    return true;   // refused before any simulation
  }
  if (!h.is_object()) return true;
  const auto s = h.find("scenario");
  if (s == h.end() || !s->is_object()) return true;
  // max_steps defaults to 100000 when absent: over budget.
  if (!within(*s, "map_size", kFuzzMapSizeMax, true) || !within(*s, "max_steps", kFuzzStepsMax, false))
    return false;
  const auto p = s->find("params");
  return p == s->end() || !p->is_object() || within(*p, "s_range", kFuzzRangeMax, true);
}

// One file per fuzzing process, rewritten for every input. It is unlinked at once and reached
// through its open descriptor, so nothing is left behind however the process ends (libFuzzer
// does not run atexit handlers when its time is up, and a crash would not either).
const std::string& trace_path() {
  static const std::string path = [] {
    char name[] = "/tmp/swarmcheck-trace-fuzz-XXXXXX";
    const int fd = mkstemp(name);
    if (fd < 0) std::abort();
    unlink(name);
    return "/proc/self/fd/" + std::to_string(fd);   // fd stays open until the process ends
  }();
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace cx = swarmcheck::conformance::exploration;
  const std::string text(reinterpret_cast<const char*>(data), size);
  if (!small_enough(text.substr(0, text.find('\n')))) return -1;
  {
    std::ofstream out(trace_path(), std::ios::binary | std::ios::trunc);
    out << text;
    if (!out.flush()) std::abort();
  }
  for (const cx::Engine engine : {cx::Engine::impl, cx::Engine::model}) {
    try {
      const cx::ReplayResult r = cx::replay_trace(trace_path(), engine);
      if (r.records < 0) std::abort();
    } catch (const swarmcheck::InputError&) {
      // bad input, reported: the expected outcome for most inputs
    }
  }
  return 0;
}
