#pragma once
// What each `swarmcheck fsm` command on the library's engine needs at its peak, as a function of
// the size its construction reaches (operations.hpp's PeakModel): the bytes per state and per
// transition of the compact structures it builds, with their growth (vectors double, hash
// tables stay at most half full), plus what the process and its inputs hold. Measured, not
// guessed: tests/hardening/memory_estimate_test.cpp runs each command on a large case with
// --memory-report and holds the estimate within 1.3x of the peak resident memory.
#include <cstddef>
#include <vector>

#include "impl/supervisor/fsm.hpp"
#include "apps/swarmcheck/verb.hpp"
#include "impl/supervisor/operations.hpp"

namespace swarmcheck::cli::fsm_peaks {

using impl::supervisor::Fsm;
using impl::supervisor::NormalPeaks;
using impl::supervisor::PeakModel;

// The bytes an automaton read from a file holds (its vectors and strings).
double bytes_of(const Fsm& f);
double bytes_of(const std::vector<Fsm>& fs);

// `fsm product` of `parts` parts: the tuple table (ids, slots), the transitions, and the writer,
// which spells names as it writes; `named`: a name stored per state (is::product).
PeakModel product_command(std::size_t parts, double inputs_bytes, bool named = false);
// `fsm synth` without unobservable events: plant || spec, then the fixpoint's reverse edges and
// marks, then the supervisor restricted twice from it.
PeakModel synth_command(double inputs_bytes);
// `fsm synth` with unobservable events: plant || spec, its observer, the (state, class) pairs.
NormalPeaks normal_synth_command(double inputs_bytes, std::size_t events);
// `fsm project`: the observer's classes (sets of states and successor rows).
PeakModel project_command(double inputs_bytes, std::size_t events);
// `fsm observable`: plant || spec, then the pairs of its states compared.
PeakModel observable_product(double inputs_bytes);
PeakModel observable_pairs();
// `fsm controllable`: plant || supervisor and the passes over it.
PeakModel controllable_command(double inputs_bytes);
// `fsm compare`: the pairs of the two inclusions (one at a time).
PeakModel compare_pairs(double inputs_bytes);

}  // namespace swarmcheck::cli::fsm_peaks
