// libFuzzer target for the .fsm reader: any bytes either read as an automaton or raise one
// InputError; never a crash, a hang or a sanitizer report. What reads is written, read again,
// and must come back equal (the writer's output is always valid input).
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "impl/supervisor/fsm_io.hpp"
#include "spec/util/input_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace sv = swarmcheck::impl::supervisor;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto a = sv::read_fsm(text, "fuzz.fsm");
    if (!(sv::read_fsm(sv::write_fsm(a), "rewritten.fsm") == a)) std::abort();
  } catch (const swarmcheck::InputError&) {
    // bad input, reported: the expected outcome for most inputs
  }
  return 0;
}
