#include "impl/io/interrupt.hpp"

#include <unistd.h>

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>

namespace swarmcheck::impl::io {
namespace {

constexpr int kSlots = 64;
constexpr std::size_t kMaxPath = 4096;

struct Slot {
  std::atomic<bool> used{false};   // claimed by a writer
  std::atomic<bool> ready{false};  // path filled in: the handler may unlink it
  char path[kMaxPath];
};

// Process-wide by necessity: a signal handler can reach only static state (interrupt.hpp).
std::array<Slot, kSlots>& slots() {
  static std::array<Slot, kSlots> s;
  return s;
}

void say(const char* text) {
  const ssize_t ignored = ::write(STDERR_FILENO, text, std::strlen(text));
  (void)ignored;
}

extern "C" void on_interrupt(int sig) {
  for (Slot& s : slots())
    if (s.ready.load(std::memory_order_acquire)) ::unlink(s.path);
  say(sig == SIGINT ? "\nswarmcheck: interrupted (SIGINT); outputs left as they were\n"
      : sig == SIGTERM ? "swarmcheck: terminated (SIGTERM); outputs left as they were\n"
                       : "swarmcheck: hung up (SIGHUP); outputs left as they were\n");
  ::_exit(128 + sig);
}

}  // namespace

void install_interrupt_cleanup() {
  static std::atomic<bool> installed{false};
  if (installed.exchange(true)) return;
  slots();   // constructed before any handler can run
  struct sigaction sa {};
  sa.sa_handler = on_interrupt;
  sigemptyset(&sa.sa_mask);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&sa.sa_mask, sig);   // one handler at a time
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction old {};
    // A signal ignored by the parent (nohup, a shell's background job) stays ignored.
    if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
    ::sigaction(sig, &sa, nullptr);
  }
}

int register_temp_file(const char* path) {
  if (std::strlen(path) >= kMaxPath) return -1;
  auto& all = slots();
  for (int k = 0; k < kSlots; ++k) {
    bool expected = false;
    if (!all[k].used.compare_exchange_strong(expected, true)) continue;
    std::strcpy(all[k].path, path);
    all[k].ready.store(true, std::memory_order_release);
    return k;
  }
  return -1;
}

void release_temp_file(int slot) {
  if (slot < 0 || slot >= kSlots) return;
  auto& s = slots()[slot];
  s.ready.store(false, std::memory_order_release);
  s.used.store(false, std::memory_order_release);
}

}  // namespace swarmcheck::impl::io
