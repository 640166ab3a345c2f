#pragma once
// Opening a file a user named as input. A regular file is read whole; a pipe (`<(...)`) is read
// up to kMaxPipedInputBytes; a folder, a device (/dev/zero would be read until memory runs out)
// or a socket is refused with an InputError naming the path and what it is. A named pipe no
// program writes to reads as empty instead of waiting for ever.
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "spec/util/input_error.hpp"

namespace swarmcheck::io_input {

inline constexpr std::size_t kMaxPipedInputBytes = std::size_t{1} << 30;   // 1 GiB

// InputError unless `path` is a regular file or (allow_pipe) a pipe. `what`: "scenario file", ...
inline void check_input_file(const std::string& path, const std::string& what, bool allow_pipe = true) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) throw InputError(path, "cannot open the " + what + ": no such file");
  switch (st.type()) {
    case fs::file_type::regular: return;
    case fs::file_type::fifo:
      if (allow_pipe) return;
      throw InputError(path, "is a pipe; the " + what + " is read more than once: give a regular file");
    case fs::file_type::directory: throw InputError(path, "is a folder; expected the " + what);
    case fs::file_type::character: throw InputError(path, "is a character device, not a file; expected the " + what);
    case fs::file_type::block: throw InputError(path, "is a block device, not a file; expected the " + what);
    case fs::file_type::socket: throw InputError(path, "is a socket, not a file; expected the " + what);
    default: throw InputError(path, "is not a regular file; expected the " + what);
  }
}

// The whole content of an input file (check_input_file's rules).
inline std::string read_input_file(const std::string& path, const std::string& what) {
  check_input_file(path, what);
  if (std::filesystem::is_regular_file(path)) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, "cannot open the " + what + " for reading");
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw InputError(path, "cannot read the " + what);
    return text.str();
  }
  // A pipe: opened without blocking (a named pipe with no writer would block the open for ever),
  // then read blocking until its writer closes it.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw InputError(path, "cannot open the " + what + " for reading");
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  std::string text;
  char chunk[1 << 16];
  for (;;) {
    const ssize_t got = ::read(fd, chunk, sizeof chunk);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) break;
    text.append(chunk, static_cast<std::size_t>(got));
    if (text.size() > kMaxPipedInputBytes) {
      ::close(fd);
      throw InputError(path, "more than 1 GiB read from a pipe: too large for a " + what);
    }
  }
  ::close(fd);
  return text;
}

}  // namespace swarmcheck::io_input
