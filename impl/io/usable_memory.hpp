#pragma once
// The memory this process may use, and the default limit swarmcheck's budgets refuse work
// beyond (the CLI's --memory-limit, the Python package's memory_limit).
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace swarmcheck::impl::io {

// The memory this process may have: the machine's physical memory, or less where a limit says so
// (`ulimit -v`, a container's cgroup memory limit), since beyond those an allocation fails or
// the process is killed whatever the machine has.
inline std::uint64_t usable_memory() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  std::uint64_t bytes = pages > 0 && page > 0 ? static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page)
                                              : std::uint64_t{32} << 30;
  struct rlimit as {};
  if (::getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) bytes = std::min<std::uint64_t>(bytes, as.rlim_cur);
  // A control group may cap memory, and so may each group above it: cgroup v2 ("0::/path" in
  // /proc/self/cgroup, memory.max: "max" or bytes) or v1 ("N:memory:/path",
  // memory/.../memory.limit_in_bytes: bytes, about 2^63 for none).
  const auto cap_along = [&bytes](std::string group, const std::string& root, const char* file) {
    for (;;) {
      if (std::FILE* f = std::fopen((root + group + "/" + file).c_str(), "r")) {
        unsigned long long cap = 0;
        if (std::fscanf(f, "%llu", &cap) == 1 && cap > 0) bytes = std::min<std::uint64_t>(bytes, cap);
        std::fclose(f);
      }
      if (group.empty()) break;
      const std::size_t slash = group.rfind('/');
      group.resize(slash == std::string::npos ? 0 : slash);
    }
  };
  if (std::FILE* f = std::fopen("/proc/self/cgroup", "r")) {
    char line[4096];
    while (std::fgets(line, sizeof line, f)) {
      std::string_view text(line);
      const auto path_after = [&](std::string_view prefix_end) {
        std::string group(text.substr(text.find(prefix_end) + prefix_end.size()));
        while (!group.empty() && (group.back() == '\n' || group.back() == '/')) group.pop_back();
        return group;
      };
      if (text.starts_with("0::")) cap_along(path_after("0::"), "/sys/fs/cgroup", "memory.max");
      else if (text.find(":memory:") != std::string_view::npos)
        cap_along(path_after(":memory:"), "/sys/fs/cgroup/memory", "memory.limit_in_bytes");
    }
    std::fclose(f);
  }
  return bytes;
}

// The default memory limit: three quarters of usable_memory().
inline std::uint64_t default_memory_limit() { return usable_memory() / 4 * 3; }

}  // namespace swarmcheck::impl::io
