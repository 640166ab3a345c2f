#include "impl/io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <filesystem>
#include <random>

#include "impl/io/interrupt.hpp"
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

// The file an output path ends up replacing: a symbolic link is followed (the link stays and
// its target gets the new content); anything but a regular file or a new name is refused,
// since a FIFO, a device or a folder cannot be replaced whole and atomically.
std::string output_target(const std::string& path) {
  if (path.empty()) throw InputError("", "an output path is empty");
  std::error_code ec;
  std::string target = path;
  if (fs::is_symlink(fs::symlink_status(path, ec))) {
    // Followed link by link: weakly_canonical of a link to a file not made yet stops at the link
    // itself, and the rename would replace the link.
    fs::path link = path;
    for (int hops = 0; fs::is_symlink(fs::symlink_status(link, ec)); ++hops) {
      if (hops == 40) throw InputError(path, "is a symbolic link that cannot be followed: too many levels of links");
      fs::path pointed = fs::read_symlink(link, ec);
      if (ec) throw InputError(path, "is a symbolic link that cannot be read: " + ec.message());
      link = pointed.is_relative() ? link.parent_path() / pointed : pointed;
    }
    const fs::path resolved = fs::weakly_canonical(link, ec);
    if (ec) throw InputError(path, "is a symbolic link that cannot be followed: " + ec.message());
    target = resolved.string();
  }
  const fs::file_status st = fs::status(target, ec);
  switch (st.type()) {
    case fs::file_type::not_found:
    case fs::file_type::regular: return target;
    case fs::file_type::directory: throw InputError(path, "is a folder; expected a file path for the output");
    case fs::file_type::fifo: throw InputError(path, "is a FIFO (named pipe), not a regular file: outputs are written whole and atomically; give a file path");
    case fs::file_type::character:
    case fs::file_type::block: throw InputError(path, "is a device, not a regular file: outputs are written whole and atomically; give a file path");
    default: throw InputError(path, "is not a regular file: outputs are written whole and atomically; give a file path");
  }
}

}  // namespace

AtomicFile::AtomicFile(std::string path)
    : path_(std::move(path)), target_(output_target(path_)), temp_(temp_name_for(target_)) {
  temp_slot_ = register_temp_file(temp_.c_str());
  out_.open(temp_, std::ios::binary | std::ios::trunc);
  if (!out_) {
    release_temp_file(temp_slot_);
    throw InputError(path_, "cannot write this file (does its folder exist, may it be written?)");
  }
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  out_.close();
  std::error_code ignored;
  fs::remove(temp_, ignored);
  release_temp_file(temp_slot_);
}

void AtomicFile::commit() {
  out_.close();
  if (!out_) throw InputError(path_, "writing failed (disk full?)");
  if (!sync_file(temp_)) throw InputError(path_, "writing failed: the data could not be flushed to disk");
  std::error_code ec;
  fs::rename(temp_, target_, ec);
  if (ec) throw InputError(path_, "cannot replace the file: " + ec.message());
  committed_ = true;
  release_temp_file(temp_slot_);
}

void check_output_path(const std::string& path) {
  const fs::path target = output_target(path);
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    throw InputError(path, "cannot write this file: its folder " + folder.string() + " does not exist");
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    throw InputError(path, "cannot write this file: its folder " + folder.string() + " may not be written");
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

void refuse_output_that_is_another_output(const std::string& output, const std::string& flag,
                                          const std::string& other, const std::string& other_flag) {
  if (output.empty() || other.empty()) return;
  // Outputs usually do not exist yet (equivalent() is false then): compared as the files they
  // will be written to, links followed.
  std::error_code ec;
  const auto where = [&](const std::string& p) {
    try {
      return fs::weakly_canonical(fs::absolute(output_target(p)), ec).string();
    } catch (const InputError&) {
      return p;   // refused when it is opened, with its own message
    }
  };
  if (output == other || std::filesystem::equivalent(output, other, ec) || where(output) == where(other))
    throw InputError(output, "is also the " + other_flag + " output of this command: give " + flag + " another file");
}

}  // namespace swarmcheck::impl::io
