#include "impl/dse/journal.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "spec/util/input_error.hpp"
#include "spec/util/json_text.hpp"

namespace swarmcheck::dse {
namespace {

void write_all(int fd, const std::string& text, const std::string& path) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw InputError(path, std::string("cannot append to the journal: ") + std::strerror(errno));
    done += static_cast<std::size_t>(n);
  }
}

}  // namespace

Journal::Journal(std::string path) : path_(std::move(path)) {
  std::string last_char;
  {
    std::ifstream in(path_, std::ios::binary);
    std::string line;
    while (std::getline(in, line)) {
      // A line that is not a point's runs (cut by a crash, or anything else) is skipped; read
      // with the JSON reader, so a line nested 300 000 deep is one of those, not a crash.
      try {
        const json_io::Json j = json_io::parse_json_text(line, path_);
        if (!j.is_object()) {
          ++skipped_;
          continue;
        }
        PointRuns p = point_runs_from_json(j);
        std::string key = p.key;
        entries_.insert_or_assign(std::move(key), std::move(p));
      } catch (const InputError&) {
        ++skipped_;
      }
    }
  }
  fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd_ < 0) throw InputError(path_, std::string("cannot open the journal: ") + std::strerror(errno));
  // A line cut by a crash has no newline: end it, so the next line starts clean.
  const off_t size = ::lseek(fd_, 0, SEEK_END);
  if (size > 0) {
    char c = 0;
    const int rfd = ::open(path_.c_str(), O_RDONLY | O_CLOEXEC);
    if (rfd >= 0) {
      if (::pread(rfd, &c, 1, size - 1) == 1 && c != '\n') write_all(fd_, "\n", path_);
      ::close(rfd);
    }
  }
}

Journal::~Journal() {
  if (fd_ < 0) return;
  if (dirty_) ::fdatasync(fd_);
  ::close(fd_);
}

void Journal::sync() {
  if (::fdatasync(fd_) != 0) throw InputError(path_, std::string("cannot flush the journal: ") + std::strerror(errno));
  last_sync_ = std::chrono::steady_clock::now();
  dirty_ = false;
}

const PointRuns* Journal::find(const std::string& key) const {
  const auto it = entries_.find(key);
  return it == entries_.end() ? nullptr : &it->second;
}

void Journal::append(const PointRuns& p, const std::string& label) {
  json_io::Json j = to_json(p);
  json_io::Json line{{"key", j["key"]}, {"point", label}, {"runs", j["runs"]}};
  write_all(fd_, line.dump() + "\n", path_);
  dirty_ = true;
  if (std::chrono::steady_clock::now() - last_sync_ >= kSyncInterval) sync();
  entries_.insert_or_assign(p.key, p);
}

}  // namespace swarmcheck::dse
