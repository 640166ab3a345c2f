#include "apps/swarmcheck/stop_request.hpp"

#include <unistd.h>

#include <cstring>

namespace swarmcheck::cli {
namespace {

// Process-wide by necessity: a signal handler can reach only static state.
std::atomic<bool> g_stop{false};
std::atomic<int> g_signal{0};
std::atomic<const char*> g_message{nullptr};

extern "C" void on_stop_signal(int sig) {
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
  sa.sa_flags = SA_RESETHAND;
  sigemptyset(&sa.sa_mask);
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
