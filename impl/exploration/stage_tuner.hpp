#pragma once
// Chooses, run by run of some work (the Environment: a planning step's decisions and deposits),
// between the parallel strips (band_schedule.hpp, strip_schedule.hpp) and one thread by timing
// both; "stage" below is one such run. The two give the same bits (tests/conformance/threads_test.cpp),
// so the choice changes only the speed, and only the machine can tell which is faster: on a
// 2-core EPYC VM the strips won at 10^4 robots (1.34x); on a 2-core Xeon VM the strip schedule
// lost everywhere (10^4 robots on 1024^2: 0.70x; 10^6 robots: 0.65x), with the same code and work.
//
// Policy: trials alternate the modes (parallel first) until each has kTrials times, or until
// each has one and one mode took kClearlySlower times the other's (a long stage of 10^6 robots
// need not be tried three times to see it). Then the mode with the smaller median of its last
// (up to) kTrials times runs, and now and then the other runs as a probe, so a change in the
// work (robots spreading out) or in the machine's load is seen: the first probe after
// kReprobeEvery stages, and the interval doubles (up to kReprobeMax) each time a probe leaves
// the choice as it was, and starts again from kReprobeEvery when the choice changes (by a probe
// or by the chosen mode's own times). A probe is judged on fresh times only: kTrials timed
// stages of the other mode, ended after kProbeSlowToEnd of them took kClearlySlower times the
// chosen mode's median. (Ended after one such stage, a probe that met one cold stage, its
// caches emptied by other work, kept the slower mode for up to kReprobeMax stages: on a 2-core
// Xeon VM, bench_exploration's threads/cli rows, which alternate two simulations every 16
// steps, ran one thread in 40 % of 10^4-robot steps where strips were 1.3-1.5x faster. A probe
// of one stage, compared
// through a median with two times from long before, kept a choice that one burst of the
// machine's noise had made for hundreds of stages: on a shared 2-core VM a tenth of the stages
// ran on the slower mode.) A stage right after a change of mode runs with caches warmed by the
// other mode (the strips' cells in two cores' caches, or all in one): its time is dropped and the
// same mode runs again, so every time compared is of a warm stage.
#include <algorithm>
#include <array>
#include <cstdint>

namespace swarmcheck::impl::exploration {

class StageTuner {
 public:
  static constexpr int kTrials = 3;
  static constexpr int64_t kReprobeEvery = 32;
  static constexpr int64_t kReprobeMax = 1024;
  static constexpr double kClearlySlower = 1.25;
  static constexpr int kProbeSlowToEnd = 2;

  // Whether the next stage should run on the strips.
  bool next_parallel() const {
    if (repeat_) return last_parallel_;   // the last stage warmed the caches up for this one
    if (!decided()) return count_[kParallel] <= count_[kSequential];
    if (probe_left_ > 0) return probe_parallel_;
    const bool best = faster_is_parallel();
    return since_probe_ + 1 >= interval_ ? !best : best;
  }
  // A stage ran on the strips (or on one thread) and took `ns` nanoseconds.
  void record(bool parallel, int64_t ns) {
    const bool chosen = decided();
    const bool best_before = chosen && faster_is_parallel();
    const bool switched = stages_ == 0 || parallel != last_parallel_;
    ++stages_;
    last_parallel_ = parallel;
    repeat_ = switched;
    const int m = parallel ? kParallel : kSequential;
    if (chosen && probe_left_ == 0 && parallel != best_before) {   // a probe's first (warm-up) stage
      probe_left_ = kTrials;
      probe_slow_ = 0;
      probe_parallel_ = parallel;
      best_at_probe_ = best_before;
      count_[m] = 0;   // the probe is judged on its own times
    }
    if (!switched) {   // a warm stage: compared
      times_[m][static_cast<std::size_t>(count_[m] % kTrials)] = ns;
      ++count_[m];
    }
    if (!chosen) {
      decided_ = decided();   // latched: a probe clears its mode's times, not the decision
      return;
    }
    if (probe_left_ == 0) {   // a chosen stage; its own times may change the choice
      if (faster_is_parallel() != best_before) {
        since_probe_ = 0;
        interval_ = kReprobeEvery;
      } else {
        ++since_probe_;
      }
      return;
    }
    if (switched) return;
    const auto chosen_median = static_cast<double>(median(best_at_probe_ ? kParallel : kSequential));
    if (static_cast<double>(ns) >= kClearlySlower * chosen_median) ++probe_slow_;
    if (--probe_left_ > 0 && probe_slow_ < kProbeSlowToEnd) return;
    probe_left_ = 0;   // the probe is over
    since_probe_ = 0;
    interval_ = faster_is_parallel() == best_at_probe_ ? std::min(2 * interval_, kReprobeMax) : kReprobeEvery;
  }
  // What it would choose now, were it not probing (for tests and reports).
  bool faster_is_parallel() const { return median(kParallel) < median(kSequential); }
  // The trials are over.
  bool decided() const {
    if (decided_) return true;
    if (count_[kParallel] >= kTrials && count_[kSequential] >= kTrials) return true;
    if (count_[kParallel] == 0 || count_[kSequential] == 0) return false;
    const auto p = static_cast<double>(median(kParallel)), s = static_cast<double>(median(kSequential));
    return p >= kClearlySlower * s || s >= kClearlySlower * p;
  }

 private:
  enum Mode : int { kParallel = 0, kSequential = 1 };
  int64_t median(int m) const {
    const auto n = static_cast<std::size_t>(std::min<int64_t>(count_[m], kTrials));
    if (n == 0) return 0;
    std::array<int64_t, kTrials> t = times_[m];
    std::nth_element(t.begin(), t.begin() + static_cast<std::ptrdiff_t>(n / 2), t.begin() + static_cast<std::ptrdiff_t>(n));
    return t[n / 2];
  }
  std::array<std::array<int64_t, kTrials>, 2> times_{};   // the last kTrials times, a ring each
  std::array<int64_t, 2> count_{};       // times in each ring (since a probe's start, for its mode)
  int64_t since_probe_ = 0;              // stages run by choice since the last probe
  int64_t interval_ = kReprobeEvery;     // of the next probe
  int64_t stages_ = 0;
  int probe_left_ = 0;                   // timed stages the running probe still needs
  int probe_slow_ = 0;                   // of its timed stages, those clearly slower
  bool decided_ = false;                 // latched: the trials are over
  bool probe_parallel_ = false, best_at_probe_ = false;
  bool last_parallel_ = false, repeat_ = false;
};

}  // namespace swarmcheck::impl::exploration
