#pragma once
// Ctrl-C (SIGINT) or SIGTERM as a request to stop cleanly, for verbs that must tidy up before they
// exit (dse keeps its journal; cosim unloads its FMUs and removes their unpacked folders). While a
// StopRequest lives, the signal sets a flag the verb polls between units of work and prints
// `message`; a second signal ends the process at once, as impl/io/interrupt.hpp's handler does
// (temporary files and folders removed, status 128 + the first signal). Outside one,
// impl/io/interrupt.hpp's handler applies (remove temporary files, exit).
#include <atomic>
#include <csignal>

namespace swarmcheck::cli {

class StopRequest {
 public:
  explicit StopRequest(const char* message);
  ~StopRequest();
  StopRequest(const StopRequest&) = delete;
  StopRequest& operator=(const StopRequest&) = delete;

  bool requested() const { return signal_number() != 0; }
  int signal_number() const;                // 0, SIGINT or SIGTERM
  int exit_status() const { return 128 + signal_number(); }   // 130, 143
  // The flag itself, for code that polls a std::atomic<bool> (the DSE sweep).
  std::atomic<bool>& flag() const;

 private:
  struct sigaction old_int_ {};
  struct sigaction old_term_ {};
};

}  // namespace swarmcheck::cli
