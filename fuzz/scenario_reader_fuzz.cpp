// libFuzzer target for the scenario reader (spec/exploration/scenario.hpp): any bytes either
// parse as a valid scenario or raise one InputError; never another exception, a crash, a hang
// or a sanitizer report. A scenario that reads is written as the DSE, the server and every trace
// header write it (json_io::to_json), read again, and must come back the same. The reader's fast
// path and the whole-DOM reader must agree: the same scenario, or the same message.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "spec/exploration/scenario.hpp"
#include "spec/util/hana_json.hpp"
#include "spec/util/input_error.hpp"

namespace {
std::string outcome(swarmcheck::exploration::Scenario (*read)(const std::string&, const std::string&),
                    const std::string& text) {
  try {
    return swarmcheck::json_io::to_json(read(text, "fuzz.json")).dump();
  } catch (const swarmcheck::InputError& e) {
    return std::string("error: ") + e.what();
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace ex = swarmcheck::exploration;
  namespace json_io = swarmcheck::json_io;
  const std::string text(reinterpret_cast<const char*>(data), size);
  if (outcome(ex::parse_scenario, text) != outcome(ex::parse_scenario_dom, text)) std::abort();
  try {
    const ex::Scenario s = ex::parse_scenario(text, "fuzz.json");
    const json_io::Json written = json_io::to_json(s);
    const ex::Scenario again = ex::parse_scenario(written.dump(), "rewritten.json");
    if (json_io::to_json(again) != written) std::abort();
    if (ex::free_cell_count(again) < 0) std::abort();
  } catch (const swarmcheck::InputError&) {
    // bad input, reported: the expected outcome for most inputs
  }
  return 0;
}
