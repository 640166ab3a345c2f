#pragma once
// Running the swarmcheck binary for the mutation test: fork and exec with a time limit and a
// memory cap, stdout and stderr kept apart, a signal reported as a signal. kBin and kSource come
// from the SWARMCHECK_BIN and SWARMCHECK_SOURCE_DIR compile definitions of the test target.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace swarmcheck::testing::mutation {

inline const std::string kBin = SWARMCHECK_BIN;
inline const std::string kSource = SWARMCHECK_SOURCE_DIR;
inline const std::string kPreexisting = "PRE-EXISTING OUTPUT: these bytes must survive a failed command\n";

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kAddressSanitizer = true;
#else
inline constexpr bool kAddressSanitizer = false;
#endif
#else
inline constexpr bool kAddressSanitizer = false;
#endif

// Running the binary. tests/util/shell.hpp's run_binary goes through popen: it has no time limit
// and WEXITSTATUS of a process killed by a signal reads as 0. This one forks and execs directly
// (no shell quoting), keeps stdout and stderr apart, kills the process group at the deadline,
// reports a signal as a signal, and caps the address space (2 GiB by default; under
// AddressSanitizer, which needs a huge address space, the resident set instead) so an input that
// makes the binary allocate without bound ends as bad_alloc (status 3) instead of waking the OOM
// killer.

struct Outcome {
  int status = -1;  // exit status when the process exited
  int signal = 0;   // the signal when it was killed by one
  bool timed_out = false;
  std::string out, err;
};

inline Outcome run_swarmcheck(const std::vector<std::string>& args, std::chrono::milliseconds limit,
                              std::size_t memory_mib = 2048) {
  int out_pipe[2], err_pipe[2];
  if (::pipe2(out_pipe, O_CLOEXEC) != 0 || ::pipe2(err_pipe, O_CLOEXEC) != 0) {
    ADD_FAILURE() << "pipe2: " << std::strerror(errno);
    return {};
  }
  std::vector<std::string> argv_s{kBin};
  argv_s.insert(argv_s.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argv_s) argv.push_back(a.data());
  argv.push_back(nullptr);
  // A sanitizer's report exits 1 by default, which reads as a verdict here: make it 99.
  auto options = [](const char* name, const std::string& more) {
    const char* old = std::getenv(name);
    return std::string(old ? old : "") + (old && *old ? ":" : "") + more;
  };
  const std::string asan_options =
      options("ASAN_OPTIONS",
              "exitcode=99" + (kAddressSanitizer ? ":hard_rss_limit_mb=" + std::to_string(memory_mib) : std::string()));
  const std::string ubsan_options = options("UBSAN_OPTIONS", "halt_on_error=1:exitcode=99");
  std::vector<std::string> env_s{"ASAN_OPTIONS=" + asan_options, "UBSAN_OPTIONS=" + ubsan_options};
  for (char** e = environ; *e; ++e)
    if (std::strncmp(*e, "ASAN_OPTIONS=", 13) != 0 && std::strncmp(*e, "UBSAN_OPTIONS=", 14) != 0)
      env_s.emplace_back(*e);
  std::vector<char*> envp;
  for (auto& e : env_s) envp.push_back(e.data());
  envp.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::setpgid(0, 0);
    const int null_in = ::open("/dev/null", O_RDONLY);
    ::dup2(null_in, 0);
    ::dup2(out_pipe[1], 1);
    ::dup2(err_pipe[1], 2);
    rlimit core{0, 0};
    ::setrlimit(RLIMIT_CORE, &core);
    if (!kAddressSanitizer) {
      const rlim_t cap = rlim_t{memory_mib} << 20;
      rlimit as{cap, cap};
      ::setrlimit(RLIMIT_AS, &as);
    }
    ::execve(argv[0], argv.data(), envp.data());
    ::_exit(127);
  }
  ::setpgid(pid, pid);  // also from here, so the kill below reaches it even before the child runs
  ::close(out_pipe[1]);
  ::close(err_pipe[1]);
  Outcome o;
  const auto deadline = std::chrono::steady_clock::now() + limit;
  pollfd fds[2] = {{out_pipe[0], POLLIN, 0}, {err_pipe[0], POLLIN, 0}};
  std::string* sinks[2] = {&o.out, &o.err};
  int open_fds = 2;
  bool killed = false;
  while (open_fds > 0) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0 && !killed) {
      ::kill(-pid, SIGKILL);
      killed = true;
      o.timed_out = true;
    }
    const int n = ::poll(fds, 2, killed ? 1000 : static_cast<int>(std::max<long long>(1, left.count())));
    if (n < 0 && errno == EINTR) continue;
    if (n == 0 && killed) break;  // a grandchild holds the pipe; give up on it
    for (int i = 0; i < 2; ++i) {
      if (fds[i].fd < 0 || fds[i].revents == 0) continue;
      char buf[8192];
      const ssize_t got = ::read(fds[i].fd, buf, sizeof buf);
      if (got > 0) {
        if (sinks[i]->size() < (1u << 20)) sinks[i]->append(buf, static_cast<std::size_t>(got));
      } else if (got == 0 || errno != EINTR) {
        ::close(fds[i].fd);
        fds[i].fd = -1;
        --open_fds;
      }
    }
  }
  for (auto& f : fds)
    if (f.fd >= 0) ::close(f.fd);
  int ws = 0;
  if (!killed && ::waitpid(pid, &ws, WNOHANG) == 0) {
    // Both pipes closed but the process is still there (it closed them itself): wait out the rest.
    while (::waitpid(pid, &ws, WNOHANG) == 0) {
      if (std::chrono::steady_clock::now() > deadline) {
        ::kill(-pid, SIGKILL);
        o.timed_out = true;
        ::waitpid(pid, &ws, 0);
        break;
      }
      ::usleep(1000);
    }
  } else if (killed) {
    ::waitpid(pid, &ws, 0);
  }
  if (WIFEXITED(ws)) o.status = WEXITSTATUS(ws);
  if (WIFSIGNALED(ws)) o.signal = WTERMSIG(ws);
  return o;
}

}  // namespace swarmcheck::testing::mutation
