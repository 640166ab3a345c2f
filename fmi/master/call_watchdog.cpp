#include "fmi/master/call_watchdog.hpp"

#include <setjmp.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace swarmcheck::fmi::master {
namespace {

// A real-time signal nothing else in swarmcheck uses (glibc keeps the first few for itself).
int cut_signal() { return SIGRTMAX - 1; }

// The calling thread's call in progress (see the header): where to jump, and whose.
thread_local sigjmp_buf* t_jump = nullptr;
thread_local const std::atomic<uint64_t>* t_in_call = nullptr;
thread_local const std::atomic<uint64_t>* t_cut = nullptr;

void on_cut_signal(int) {
  // Only the call the watcher decided to cut off, and only while it is in progress.
  if (!t_jump || !t_in_call || !t_cut) return;
  const uint64_t id = t_in_call->load(std::memory_order_acquire);
  if (id != 0 && id == t_cut->load(std::memory_order_acquire)) siglongjmp(*t_jump, 1);
}

void write_all(const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(STDERR_FILENO, text.data() + done, text.size() - done);
    if (n <= 0) return;
    done += static_cast<std::size_t>(n);
  }
}

}  // namespace

CallWatchdog::CallWatchdog(double limit_s, std::function<std::string(const Call&)> describe)
    : limit_s_(limit_s > 0 && std::isfinite(limit_s) ? limit_s : 0), describe_(std::move(describe)), owner_(pthread_self()) {
  if (!active()) return;
  struct sigaction sa {};
  sa.sa_handler = on_cut_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = 0;   // no SA_RESTART: a blocking system call in the FMU is interrupted
  sigaction(cut_signal(), &sa, &previous_);
  watcher_ = std::thread([this] { watch(); });
}

CallWatchdog::~CallWatchdog() {
  if (!active()) return;
  stop_.store(true);
  {
    std::lock_guard<std::mutex> lock(mutex_);
  }
  wake_.notify_all();
  watcher_.join();
  sigaction(cut_signal(), &previous_, nullptr);
}

void CallWatchdog::remove_if_abandoned(const std::string& path) {
  std::lock_guard<std::mutex> lock(mutex_);
  remove_.push_back(path);
}

bool CallWatchdog::run_raw(const Call& what, int (*call)(void*), void* context, int& status) {
  if (!active()) {
    status = call(context);
    return true;
  }
  sigjmp_buf jump;
  if (sigsetjmp(jump, 0) != 0) {
    // Back from the handler (the signal stays blocked after the jump: unblock it).
    in_call_.store(0, std::memory_order_release);
    t_jump = nullptr;
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, cut_signal());
    pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
    return false;
  }
  t_jump = &jump;
  t_in_call = &in_call_;
  t_cut = &cut_;
  current_instance_.store(what.instance, std::memory_order_relaxed);
  current_what_.store(what.what, std::memory_order_relaxed);
  in_call_.store(next_id_++, std::memory_order_release);
  status = call(context);
  in_call_.store(0, std::memory_order_release);
  t_jump = nullptr;
  return true;
}

void CallWatchdog::watch() {
  using clock = std::chrono::steady_clock;
  const auto limit = std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>(limit_s_));
  // Polls a few times per limit (at most every 50 ms): a call is cut off between 1 and 1.25 limits.
  const auto period = std::min<clock::duration>(limit / 4, std::chrono::milliseconds(50));
  std::unique_lock<std::mutex> lock(mutex_);
  uint64_t seen = 0;
  auto since = clock::now();
  while (!stop_.load()) {
    wake_.wait_for(lock, period);
    if (stop_.load()) break;
    const uint64_t id = in_call_.load(std::memory_order_acquire);
    const auto now = clock::now();
    if (id == 0 || id != seen) {
      seen = id;
      since = now;
      continue;
    }
    if (now - since < limit) continue;
    const Call call{current_instance_.load(std::memory_order_relaxed), current_what_.load(std::memory_order_relaxed)};
    cut_.store(id, std::memory_order_release);
    pthread_kill(owner_, cut_signal());
    // The owner comes back out of the call within moments, unless the FMU blocks the signal.
    const auto deadline = clock::now() + limit;
    while (!stop_.load() && in_call_.load(std::memory_order_acquire) == id && clock::now() < deadline)
      wake_.wait_for(lock, period);
    if (!stop_.load() && in_call_.load(std::memory_order_acquire) == id) abandon(call);
    seen = 0;
  }
}

void CallWatchdog::abandon(const Call& call) {
  char limit[32];
  std::snprintf(limit, sizeof limit, "%g", limit_s_);
  write_all("swarmcheck cosim: " + describe_(call) + " did not return within " + limit +
            " s, the call time limit, and could not be interrupted (it blocks signals): the FMUs' folders "
            "are removed and the process ends without freeing them\n");
  for (const std::string& path : remove_) {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  ::_exit(1);
}

}  // namespace swarmcheck::fmi::master
