#pragma once
// The first field where two step records differ, as "path a vs b", or "" when they are equal.
#include <string>

#include "spec/exploration/types.hpp"
#include "spec/util/hana_diff.hpp"

namespace swarmcheck::exploration::testing {

inline std::string first_difference_text(const StepRecord& a, const StepRecord& b) {
  const auto d = json_io::first_difference(a, b);
  return d ? d->path + " " + d->a + " vs " + d->b : "";
}

}  // namespace swarmcheck::exploration::testing
