#pragma once
// A wall-clock limit on the FMU calls the master makes (the per-step limit of `cosim
// --step-timeout`). An FMU's fmi2DoStep may block: the thesis's Environment waits every step
// for a client of its live view that may never come. A thread watches the call in progress; at
// the limit it sends the calling thread a signal whose handler jumps out of the FMU's code back
// into run() (siglongjmp), which returns false, and the master stops the run, frees the FMUs and
// removes their folders. An FMU that blocks that signal cannot be left this way: after the limit
// again the watching thread writes the message, removes the registered folders and files, and
// ends the process with status 1 (the FMUs are then not freed; the process's end frees them).
//
// Leaving a call by a jump skips the frames between run() and the FMU: the call passed to run()
// must own no object with a destructor (the master's calls are a function pointer and numbers).
// The jump target and the call's identity are in thread_local variables: a signal handler can
// reach nothing else (the one process-wide state of the master, like impl/io/interrupt.hpp's).
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <pthread.h>
#include <signal.h>
#include <string>
#include <thread>
#include <vector>

namespace swarmcheck::fmi::master {

class CallWatchdog {
 public:
  // What the message names: the call's instance and what the call was.
  struct Call {
    std::size_t instance = 0;
    const char* what = "";   // a string literal ("fmi2DoStep", ...)
  };
  // limit_s <= 0: calls are not watched (run() only calls). `describe` names a call in the
  // message of a process ended from the watching thread (called there, while the call blocks).
  CallWatchdog(double limit_s, std::function<std::string(const Call&)> describe);
  ~CallWatchdog();
  CallWatchdog(const CallWatchdog&) = delete;
  CallWatchdog& operator=(const CallWatchdog&) = delete;

  bool active() const { return limit_s_ > 0; }
  double limit_s() const { return limit_s_; }
  // Removed if the process has to be ended from the watching thread.
  void remove_if_abandoned(const std::string& path);

  // Runs call() (returning an fmi2Status) into `status`; false when it was cut off at the limit.
  template <class F>
  bool run(const Call& what, F call, int& status) {
    return run_raw(what, [](void* f) -> int { return static_cast<int>((*static_cast<F*>(f))()); }, &call, status);
  }

 private:
  bool run_raw(const Call& what, int (*call)(void*), void* context, int& status);
  void watch();
  [[noreturn]] void abandon(const Call& call);

  double limit_s_;
  struct sigaction previous_ {};   // the signal's handler before this one, restored at the end
  std::function<std::string(const Call&)> describe_;
  pthread_t owner_{};                 // the thread that makes the calls
  std::atomic<uint64_t> in_call_{0};  // the id of the call in progress, 0 between calls
  std::atomic<uint64_t> cut_{0};      // the id of the call being cut off
  uint64_t next_id_ = 1;              // the owner's only
  // The call in progress, for the message (read by the watcher while it blocks).
  std::atomic<std::size_t> current_instance_{0};
  std::atomic<const char*> current_what_{""};
  std::atomic<bool> stop_{false};
  std::mutex mutex_;
  std::condition_variable wake_;
  std::vector<std::string> remove_;   // guarded by mutex_
  std::thread watcher_;
};

}  // namespace swarmcheck::fmi::master
