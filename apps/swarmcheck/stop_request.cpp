#include "apps/swarmcheck/stop_request.hpp"

#include <unistd.h>

#include <cstring>

#include "impl/io/interrupt.hpp"

namespace swarmcheck::cli {
namespace {

// Process-wide by necessity: a signal handler can reach only static state.
std::atomic<bool> g_stop{false};
std::atomic<int> g_signal{0};
std::atomic<const char*> g_message{nullptr};

extern "C" void on_stop_signal(int sig) {
  // The second signal does not wait for the tidy stop: temporary files and folders (cosim's
  // unpacked FMUs) are removed and the process ends now, with the first signal's status.
  if (g_stop.load()) {
    const int first = g_signal.load();
    impl::io::exit_now(128 + (first != 0 ? first : sig),
                       "swarmcheck: stopped at once (second signal); temporary files removed, outputs left as they were\n");
  }
  g_signal.store(sig);
  g_stop.store(true);
  if (const char* m = g_message.load()) {
    const ssize_t ignored = ::write(STDERR_FILENO, m, std::strlen(m));
    (void)ignored;
  }
}

}  // namespace

StopRequest::StopRequest(const char* message) {
  g_stop.store(false);
  g_signal.store(0);
  g_message.store(message);
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sa.sa_flags = 0;
  sigemptyset(&sa.sa_mask);
  sigaddset(&sa.sa_mask, SIGINT);   // one handler at a time
  sigaddset(&sa.sa_mask, SIGTERM);
  sigaction(SIGINT, &sa, &old_int_);
  sigaction(SIGTERM, &sa, &old_term_);
}

StopRequest::~StopRequest() {
  sigaction(SIGINT, &old_int_, nullptr);
  sigaction(SIGTERM, &old_term_, nullptr);
  g_message.store(nullptr);
}

int StopRequest::signal_number() const { return g_signal.load(); }
std::atomic<bool>& StopRequest::flag() const { return g_stop; }

}  // namespace swarmcheck::cli
