#pragma once
// The one way swarmcheck writes an output file: the content goes to a temporary file in the
// target's own folder (so the rename cannot cross file systems), is flushed and fsync'ed, and is
// renamed onto the target only on commit(). Until then the target keeps its old content; an
// error or an exception removes the temporary file, so a failed command leaves nothing
// half-written behind. Failures are InputError naming the path. A symbolic link is written
// through (its target is replaced); a FIFO, device or folder is refused. An interrupting signal
// removes the temporary file too (interrupt.hpp).
//
//   AtomicFile out("trace.jsonl");
//   out.stream() << ...;
//   out.commit();                       // or: write_file_atomically(path, text)
#include <fstream>
#include <string>
#include <vector>

namespace swarmcheck::impl::io {

class AtomicFile {
 public:
  explicit AtomicFile(std::string path);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();   // without commit(): the temporary file is removed, the target untouched

  std::ofstream& stream() { return out_; }
  const std::string& path() const { return path_; }
  const std::string& temp_path() const { return temp_; }
  void commit();

 private:
  std::string path_;     // as the user named it (messages)
  std::string target_;   // the file replaced on commit: path_, or the file its link points to
  std::string temp_;
  int temp_slot_ = -1;   // interrupt.hpp: removed if a signal ends the process first
  std::ofstream out_;
  bool committed_ = false;
};

// The whole content at once, atomically.
void write_file_atomically(const std::string& path, const std::string& content);

// InputError when `path` could not be written as an output (a folder, a FIFO, a device, a link
// that cannot be followed), as AtomicFile would refuse it: for a command to check its outputs
// before long work.
void check_output_path(const std::string& path);

// InputError when `output` names the same file as one of `inputs` (by path or through a link):
// a command would otherwise replace the file it reads. Empty paths are ignored.
void refuse_output_that_is_an_input(const std::string& output, const std::vector<std::string>& inputs);
// Throws InputError when `output` (given with `flag`) is the same file as `other` (given with
// `other_flag`), another output of the same command: one would overwrite the other.
void refuse_output_that_is_another_output(const std::string& output, const std::string& flag,
                                          const std::string& other, const std::string& other_flag);

}  // namespace swarmcheck::impl::io

namespace swarmcheck {
// The namespace's first name, for callers outside system B's folders that still write io::.
namespace io = impl::io;
}  // namespace swarmcheck
