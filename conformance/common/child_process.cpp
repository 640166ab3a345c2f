#include "conformance/common/child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <stdexcept>

#include "spec/util/input_error.hpp"

namespace swarmcheck::conformance {
namespace {

// The child's message: one tag byte ('R' result, 'X' exception), then the text.
constexpr char kResult = 'R';
constexpr char kThrew = 'X';

void write_all(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) _exit(126);   // the parent is gone: nothing left to tell
    data += n;
    size -= static_cast<std::size_t>(n);
  }
}

[[noreturn]] void child_main(int fd, CaseProgress::Shared& shared,
                             const std::function<std::string(CaseProgress&)>& work) {
  const rlimit no_core{0, 0};
  ::setrlimit(RLIMIT_CORE, &no_core);
  // A fault ends the child by its signal, whatever handler the caller installed (AddressSanitizer's
  // turns a SIGSEGV into a report and exit status 1): the parent names the signal.
  for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL}) ::signal(sig, SIG_DFL);
  CaseProgress progress(shared);
  std::string message;
  try {
    message = kResult + work(progress);
  } catch (const std::exception& e) {
    message = kThrew + std::string(e.what());
  } catch (...) {
    message = kThrew + std::string("an exception of unknown type");
  }
  write_all(fd, message.data(), message.size());
  ::close(fd);
  _exit(0);   // no atexit handlers, no destructors, no flushing of the parent's buffers
}

// The page the parent and the child share (MAP_SHARED survives the fork).
class SharedPage {
 public:
  SharedPage() {
    void* p = ::mmap(nullptr, sizeof(CaseProgress::Shared), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) throw std::runtime_error(std::string("cannot map memory for a child process: ") + std::strerror(errno));
    shared_ = new (p) CaseProgress::Shared();
  }
  ~SharedPage() { ::munmap(shared_, sizeof(CaseProgress::Shared)); }
  SharedPage(const SharedPage&) = delete;
  SharedPage& operator=(const SharedPage&) = delete;
  CaseProgress::Shared& get() { return *shared_; }

 private:
  CaseProgress::Shared* shared_;
};

std::string side_name(CaseProgress::Side s) {
  switch (s) {
    case CaseProgress::Side::model: return "model";
    case CaseProgress::Side::impl: return "impl";
    case CaseProgress::Side::none: break;
  }
  return "the case";
}

}  // namespace

std::string signal_name(int signal) {
  if (const char* abbrev = ::sigabbrev_np(signal)) return std::string("SIG") + abbrev;
  return "signal " + std::to_string(signal);
}

std::string ChildEnd::describe() const {
  const std::string who = side_name(side);
  const std::string at = step >= 0 ? " at step " + std::to_string(step) : "";
  switch (how) {
    case How::finished: return who + " finished";
    case How::crashed: return who + " crashed with " + signal_name(signal) + at;
    case How::hung: {
      const auto ms = quiet.count();
      const std::string limit = ms % 1000 == 0 ? std::to_string(ms / 1000) + " s" : std::to_string(ms) + " ms";
      return who + " hung" + at + " (no progress for " + limit + ")";
    }
    case How::threw: return who + " threw" + at + ": " + output;
    case How::exited: return who + " exited with status " + std::to_string(exit_status) + at;
  }
  return who + " ended";
}

ChildEnd run_in_child(const std::function<std::string(CaseProgress&)>& work, const ChildLimits& limits) {
  SharedPage page;
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("cannot make a pipe: ") + std::strerror(errno));
  // Whatever this process has buffered for stdout and stderr goes out now, once: the child gets a
  // copy of the buffers, and would write it again if anything in it flushed them.
  std::fflush(nullptr);
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int err = errno;
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error(std::string("cannot start a child process: ") + std::strerror(err));
  }
  if (pid == 0) {
    // The case dies with the campaign: a second Ctrl-C ends the parent at once, and an orphaned
    // case would run on (found: SecondSignal tests left `conform` cases running for half an hour).
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(1);   // the parent ended before the line above
    ::close(fds[0]);
    child_main(fds[1], page.get(), work);
  }
  ::close(fds[1]);
  ChildEnd end;
  std::string received;
  bool hung = false;
  // Read until the child closes its end (it wrote everything, or died), watching its progress.
  uint64_t beats = page.get().beats.load(std::memory_order_relaxed);
  auto last_sign = std::chrono::steady_clock::now();
  const auto poll_every = std::clamp<std::chrono::milliseconds>(limits.quiet / 8, std::chrono::milliseconds(5),
                                                                 std::chrono::milliseconds(250));
  char buffer[65536];
  for (;;) {
    pollfd p{fds[0], POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(poll_every.count()));
    if (ready < 0 && errno != EINTR) break;
    if (ready > 0) {
      const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
      if (n > 0) {
        received.append(buffer, static_cast<std::size_t>(n));
        continue;
      }
      if (n == 0 || errno != EINTR) break;   // end of file: the child is done or dead
    }
    const auto now = std::chrono::steady_clock::now();
    const uint64_t seen = page.get().beats.load(std::memory_order_relaxed);
    if (seen != beats) {
      beats = seen;
      last_sign = now;
    } else if (now - last_sign >= limits.quiet) {
      ::kill(pid, SIGKILL);
      hung = true;
      break;
    }
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  end.step = page.get().step.load(std::memory_order_relaxed);
  end.cases_agreed = page.get().cases_agreed.load(std::memory_order_relaxed);
  end.side = static_cast<CaseProgress::Side>(page.get().side.load(std::memory_order_relaxed));
  if (hung) {
    end.how = ChildEnd::How::hung;
    end.quiet = limits.quiet;
  } else if (WIFSIGNALED(status)) {
    end.how = ChildEnd::How::crashed;
    end.signal = WTERMSIG(status);
  } else if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && !received.empty()) {
    end.how = received[0] == kResult ? ChildEnd::How::finished : ChildEnd::How::threw;
    end.output = received.substr(1);
  } else {
    end.how = ChildEnd::How::exited;
    end.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  return end;
}

ChildEnd thrown_at(const CaseProgress& progress, const std::string& what) {
  ChildEnd end;
  end.how = ChildEnd::How::threw;
  end.output = what;
  end.step = progress.step();
  end.side = progress.side();
  return end;
}

FirstPass run_campaign_in_child(const std::function<std::string(CaseProgress&)>& campaign, const ChildLimits& limits) {
  // The child's answer: 'R' and the report, or 'I', the InputError's where, a newline and its what().
  const ChildEnd end = run_in_child([&](CaseProgress& p) {
    try {
      return "R" + campaign(p);
    } catch (const InputError& e) {
      return "I" + e.where() + "\n" + e.what();
    }
  }, limits);
  if (end.how == ChildEnd::How::threw) throw std::runtime_error(end.output);
  if (!end.finished()) return FirstPass{std::nullopt, end.cases_agreed};
  if (!end.output.empty() && end.output[0] == 'I') {
    const std::size_t nl = end.output.find('\n');
    const std::string where = end.output.substr(1, nl - 1), what = end.output.substr(nl + 1);
    const std::string prefix = where + ": ";
    throw InputError(where, !where.empty() && what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what);
  }
  return FirstPass{end.output.substr(1), end.cases_agreed};
}

}  // namespace swarmcheck::conformance
