#pragma once
// Running a piece of a campaign in a child process, so that a crash (SIGSEGV, abort, ...) or a
// hang of the code under test ends that piece, not the campaign: the campaign gets how it ended
// ("impl crashed with SIGSEGV at step 12") and goes on to shrink it like any other difference.
//
//   ChildEnd end = run_in_child([&](CaseProgress& p) {
//     ... p.at(step, CaseProgress::Side::impl); impl.step(); ...
//     return result_as_text;               // handed back to the parent through a pipe
//   }, ChildLimits{std::chrono::seconds(60)});
//   if (end.how == ChildEnd::How::finished) use(end.output); else report(end.describe());
//
// The child is a fork() of the caller: it sees the caller's memory as it was (the case to run
// needs no serialising), and ends with _exit (nothing of the caller's is flushed or destroyed
// twice). Its progress goes through a page the two processes share, so reporting a step costs
// two stores; the parent polls it and kills the child (SIGKILL) once it has shown no progress for
// ChildLimits::quiet: a hang is "no new step for that long", so a long healthy run never counts as
// one. Core dumps are off in the child (a crash is an expected outcome here).
//
// Fork and threads: only the calling thread exists in the child. A library whose worker threads
// were started in the caller before the fork (oneTBB's) would find them gone in the child, so the
// campaigns run impl code only in children, never in the caller: the caller stays single-threaded
// and each child starts its own workers.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace swarmcheck::conformance {

// What a child tells its parent as it goes: the step it is computing and on which side.
class CaseProgress {
 public:
  enum class Side : int32_t { none = 0, model = 1, impl = 2 };
  struct Shared {
    std::atomic<int64_t> step{-1};
    std::atomic<int32_t> side{0};
    std::atomic<uint64_t> beats{0};
    std::atomic<int64_t> cases_agreed{0};
  };

  explicit CaseProgress(Shared& shared) : shared_(&shared) {}
  // Computing `step` (the run's step number) on `side` now; also a sign of life.
  void at(int64_t step, Side side) {
    shared_->step.store(step, std::memory_order_relaxed);
    shared_->side.store(static_cast<int32_t>(side), std::memory_order_relaxed);
    shared_->beats.fetch_add(1, std::memory_order_relaxed);
  }
  // A sign of life alone (long work that has no steps).
  void alive() { shared_->beats.fetch_add(1, std::memory_order_relaxed); }
  // A campaign's first `cases` cases agreed (before any failure): a second pass need not run them.
  void agreed(int64_t cases) { shared_->cases_agreed.store(cases, std::memory_order_relaxed); }
  int64_t step() const { return shared_->step.load(std::memory_order_relaxed); }
  Side side() const { return static_cast<Side>(shared_->side.load(std::memory_order_relaxed)); }

 private:
  Shared* shared_;
};

struct ChildLimits {
  // The child is stopped (and counts as hung) after this long without progress.
  std::chrono::milliseconds quiet{std::chrono::seconds(60)};
};

struct ChildEnd {
  enum class How { finished, crashed, hung, threw, exited };
  How how = How::finished;
  std::string output;             // finished: what the work returned; threw: the exception's what()
  int signal = 0;                 // crashed: the signal that ended it
  int exit_status = 0;            // exited: the status it exited with (the work never returned)
  int64_t step = -1;              // the last step it reported (-1: none)
  CaseProgress::Side side = CaseProgress::Side::none;   // ... and its side
  std::chrono::milliseconds quiet{0};                   // hung: the limit it ran into
  int64_t cases_agreed = 0;       // a campaign's cases the child saw agree before any failure

  bool finished() const { return how == How::finished; }
  // "impl crashed with SIGSEGV at step 12", "impl hung at step 3 (no progress for 60 s)",
  // "model threw std::logic_error: ..." ("the case" when no side was reported).
  std::string describe() const;
};

// Runs work in a fork of this process (see above). Throws std::runtime_error when no child can
// be made.
ChildEnd run_in_child(const std::function<std::string(CaseProgress&)>& work, const ChildLimits& limits);

// An exception caught where `progress` is (in the child itself): the end it describes, as if the
// child had thrown it ("impl threw at step 3: ...").
ChildEnd thrown_at(const CaseProgress& progress, const std::string& what);

// A whole campaign in one child process, its cases run there in-process: its report (as text), or
// no report when the child crashed or hung, and the caller runs the campaign again with each case
// in a child of its own, where the crash or the hang is a counterexample like any other; the
// cases the first child saw agree (CaseProgress::agreed) need not run again. One fork per
// campaign, not per case (a fork and the first touch of the copied pages cost milliseconds).
// An InputError of the campaign (a folder it cannot write) is thrown again here.
struct FirstPass {
  std::optional<std::string> report;
  int64_t cases_agreed = 0;
};
FirstPass run_campaign_in_child(const std::function<std::string(CaseProgress&)>& campaign, const ChildLimits& limits);

// "SIGSEGV" for SIGSEGV, "signal 64" for one without a name.
std::string signal_name(int signal);

}  // namespace swarmcheck::conformance
