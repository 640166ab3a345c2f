#pragma once
// Running the swarmcheck binary from a test: exit status and stdout + stderr together.
#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace swarmcheck::testing {

struct ShellResult {
  int status;
  std::string out;
};

inline ShellResult run_binary(const std::string& binary, const std::string& args) {
  FILE* p = popen((binary + " " + args + " 2>&1").c_str(), "r");
  std::string out;
  char buf[4096];
  while (std::size_t n = fread(buf, 1, sizeof buf, p)) out.append(buf, n);
  const int rc = pclose(p);
  return ShellResult{WEXITSTATUS(rc), out};
}

}  // namespace swarmcheck::testing
