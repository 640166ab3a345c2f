#pragma once
// The summary of a run, as `swarmcheck run --json` prints it (without the keys run_report adds).
// One definition for the command line, the harness and the Python package
// (swarmcheck/run_report.hpp), so that what the user sees is compared between the engines too, not
// only the step records.
#include "swarmcheck/run_report.hpp"

namespace swarmcheck::conformance::exploration {

using swarmcheck::exploration::run_summary;

}  // namespace swarmcheck::conformance::exploration
