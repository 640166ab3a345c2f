#include "impl/io/interrupt.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <csignal>
#include <cerrno>
#include <cstring>

namespace swarmcheck::impl::io {
namespace {

constexpr int kSlots = 64;
constexpr std::size_t kMaxPath = 4096;

struct Slot {
  std::atomic<bool> used{false};   // claimed by a writer
  std::atomic<bool> ready{false};  // path filled in: the handler may unlink it
  bool folder = false;             // a folder, removed with what it holds
  char path[kMaxPath];
};

// Process-wide by necessity: a signal handler can reach only static state (interrupt.hpp).
std::array<Slot, kSlots>& slots() {
  static std::array<Slot, kSlots> s;
  return s;
}

// Child processes to kill when the process ends at once (0: a free slot).
std::array<std::atomic<pid_t>, kSlots>& children() {
  static std::array<std::atomic<pid_t>, kSlots> c{};
  return c;
}

// Removes `name` (relative to the folder open as `at`) and, if it is a folder, what it holds,
// with system calls only (async-signal-safe: no allocation, no stdio, no locks). Links are
// removed, not followed.
void remove_tree(int at, const char* name, int depth) {
  if (::unlinkat(at, name, 0) == 0 || errno == ENOENT) return;
  if (depth > 32) return;
  const int fd = ::openat(at, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return;
  // Entries are removed as they are listed; the folder is listed again until a pass finds none.
  for (bool removed = true; removed;) {
    removed = false;
    ::lseek(fd, 0, SEEK_SET);
    alignas(8) char buffer[2048];
    for (long n; (n = ::syscall(SYS_getdents64, fd, buffer, sizeof buffer)) > 0;) {
      for (long at_byte = 0; at_byte < n;) {
        const auto* d = reinterpret_cast<const struct dirent64*>(buffer + at_byte);
        at_byte += d->d_reclen;
        if (std::strcmp(d->d_name, ".") == 0 || std::strcmp(d->d_name, "..") == 0) continue;
        remove_tree(fd, d->d_name, depth + 1);
        removed = true;
      }
    }
  }
  ::close(fd);
  ::unlinkat(at, name, AT_REMOVEDIR);
}

int claim_slot(const char* path, bool folder) {
  if (std::strlen(path) >= kMaxPath) return -1;
  auto& all = slots();
  for (int k = 0; k < kSlots; ++k) {
    bool expected = false;
    if (!all[k].used.compare_exchange_strong(expected, true)) continue;
    std::strcpy(all[k].path, path);
    all[k].folder = folder;
    all[k].ready.store(true, std::memory_order_release);
    return k;
  }
  return -1;
}

void say(const char* text) {
  const ssize_t ignored = ::write(STDERR_FILENO, text, std::strlen(text));
  (void)ignored;
}

extern "C" void on_interrupt(int sig) {
  remove_temp_files_now();
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
  children();
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

int register_temp_file(const char* path) { return claim_slot(path, false); }
int register_temp_folder(const char* path) { return claim_slot(path, true); }

void remove_temp_files_now() {
  const int saved = errno;
  // Children first: dot writes its output into a temporary file, which must not come back.
  for (auto& c : children())
    if (const pid_t pid = c.load(); pid > 0) ::kill(pid, SIGKILL);
  for (Slot& s : slots())
    if (s.ready.load(std::memory_order_acquire)) {
      if (s.folder) remove_tree(AT_FDCWD, s.path, 0);
      else ::unlink(s.path);
    }
  errno = saved;
}

void exit_now(int status, const char* message) {
  remove_temp_files_now();
  if (message) say(message);
  ::_exit(status);
}

int register_child(pid_t pid) {
  auto& all = children();
  for (int k = 0; k < kSlots; ++k) {
    pid_t expected = 0;
    if (all[k].compare_exchange_strong(expected, pid)) return k;
  }
  return -1;
}

void release_child(int slot) {
  if (slot >= 0 && slot < kSlots) children()[slot].store(0);
}

void release_temp_file(int slot) {
  if (slot < 0 || slot >= kSlots) return;
  auto& s = slots()[slot];
  s.ready.store(false, std::memory_order_release);
  s.used.store(false, std::memory_order_release);
}

}  // namespace swarmcheck::impl::io
