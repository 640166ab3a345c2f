#pragma once
// AtomicOutputFile: writes to "<path>.tmp-<pid>" and renames onto <path> on commit(); if it is
// destroyed without commit() (an error, an exception), the temporary file is removed, so a
// failed command never leaves a half-written file behind.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "spec/util/input_error.hpp"

namespace swarmcheck::cli {

class AtomicOutputFile {
 public:
  explicit AtomicOutputFile(std::string path)
      : path_(std::move(path)), tmp_(path_ + ".tmp-" + std::to_string(::getpid())) {
    out_.open(tmp_, std::ios::binary | std::ios::trunc);
    if (!out_) throw InputError(path_, "cannot write this file (does its folder exist?)");
  }
  AtomicOutputFile(const AtomicOutputFile&) = delete;
  AtomicOutputFile& operator=(const AtomicOutputFile&) = delete;
  ~AtomicOutputFile() {
    if (!committed_) {
      out_.close();
      std::error_code ec;
      std::filesystem::remove(tmp_, ec);
    }
  }
  std::ofstream& stream() { return out_; }
  void commit() {
    out_.close();
    if (!out_) throw InputError(path_, "writing failed (disk full?)");
    std::filesystem::rename(tmp_, path_);
    committed_ = true;
  }

 private:
  std::string path_;
  std::string tmp_;
  std::ofstream out_;
  bool committed_ = false;
};

}  // namespace swarmcheck::cli
