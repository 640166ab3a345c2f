// libFuzzer target for the DSE configuration reader: the text -> design space path of `swarmcheck
// dse` before any run (impl/dse/config.cpp, expression.cpp, names.cpp, design_space.cpp):
// parse_dse_config, the design space on the built-in scenario, and for the first points their
// genome, index, constraint verdict, description, key and replicate scenarios. Any bytes either
// give a design space or raise one InputError; never another exception, a crash, a hang, a stack
// overflow (a constraint nested thousands deep was one) or a sanitizer report.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "impl/dse/config.hpp"
#include "impl/dse/design_space.hpp"
#include "spec/exploration/scenario.hpp"
#include "spec/util/input_error.hpp"

namespace {

namespace dse = swarmcheck::dse;

// A point's scenario is built only when it stays small: a fuzzed map of 10^5 cells a side or 10^7
// robots is the memory budget's business (check_design_space), not the reader's.
bool small_point(const dse::DesignSpace& space, const dse::Genome& g) {
  const auto number = [&](dse::Knob k) { return space.knob_value(g, k).number; };
  return number(dse::Knob::map_size) <= 256 && number(dse::Knob::robot_count) <= 1000 &&
         number(dse::Knob::obstacle_count) <= 1000 && number(dse::Knob::replicates) <= 4;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const dse::DseConfig config = dse::parse_dse_config(text, "fuzz.dse.json");
    const dse::DesignSpace space(config, swarmcheck::exploration::default_scenario());
    const std::uint64_t points = space.size();
    for (std::uint64_t i = 0; i < points && i < 8; ++i) {
      const dse::Genome g = space.genome_of(i);
      if (space.index_of(g) != i) std::abort();   // genome_of and index_of are inverses
      (void)space.describe(g);
      if (space.violated_parameter_constraint(g) >= 0 || !small_point(space, g)) continue;
      (void)space.point_key(g);
      for (int32_t r = 0; r < space.replicates(g); ++r) (void)space.scenario(g, r);
    }
  } catch (const swarmcheck::InputError&) {
    // bad input, reported: the expected outcome for most inputs
  }
  return 0;
}
