#include "impl/io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <filesystem>
#include <random>

#include "spec/util/input_error.hpp"

namespace swarmcheck::impl::io {
namespace fs = std::filesystem;

namespace {

// "<folder>/.<name>.tmp-<pid>-<random>": hidden, next to the target, unique among writers.
std::string temp_name_for(const std::string& path) {
  const fs::path target(path);
  std::random_device rd;
  std::string name = ".";
  name += target.filename().string();
  name += ".tmp-";
  name += std::to_string(::getpid());
  name += '-';
  name += std::to_string(rd());
  return (target.parent_path() / name).string();
}

// Flushes the file's data to the disk, so a crash after the rename cannot leave it empty.
bool sync_file(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool ok = ::fsync(fd) == 0;
  ::close(fd);
  return ok;
}

}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)), temp_(temp_name_for(path_)) {
  if (path_.empty()) throw InputError("", "an output path is empty");
  out_.open(temp_, std::ios::binary | std::ios::trunc);
  if (!out_) throw InputError(path_, "cannot write this file (does its folder exist, may it be written?)");
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  out_.close();
  std::error_code ignored;
  fs::remove(temp_, ignored);
}

void AtomicFile::commit() {
  out_.close();
  if (!out_) throw InputError(path_, "writing failed (disk full?)");
  if (!sync_file(temp_)) throw InputError(path_, "writing failed: the data could not be flushed to disk");
  std::error_code ec;
  fs::rename(temp_, path_, ec);
  if (ec) throw InputError(path_, "cannot replace the file: " + ec.message());
  committed_ = true;
}

void write_file_atomically(const std::string& path, const std::string& content) {
  AtomicFile f(path);
  f.stream() << content;
  f.commit();
}

void refuse_output_that_is_an_input(const std::string& output, const std::vector<std::string>& inputs) {
  if (output.empty()) return;
  for (const std::string& input : inputs) {
    if (input.empty()) continue;
    std::error_code ec;
    if (output == input || std::filesystem::equivalent(output, input, ec))
      throw InputError(output, "is also an input of this command (" + input + "): choose another output file");
  }
}

}  // namespace swarmcheck::impl::io
