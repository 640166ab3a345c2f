#pragma once
// The resumable sweep's journal, DIR/journal.jsonl: one line per finished design point,
// {"key": <DesignSpace::point_key>, "point": "ertu_perc=0.07", "runs": [...]}. Each line is
// appended with one write(2) on an O_APPEND descriptor as soon as its point finishes, so a
// killed process loses nothing it finished; a line is either wholly there or (cut mid-write) an
// unparseable tail that reading skips. fdatasync runs at most every kSyncInterval (group commit:
// a power cut loses at most that much finished work, which a rerun recomputes) and on close;
// syncing every line would cost more than a small run does.
// Rerunning the same command reads the journal and computes only the points it lacks; a key
// hashes the point's full scenarios, so a changed base scenario or parameter never matches an
// old line.
#include <chrono>
#include <map>
#include <string>

#include "impl/dse/evaluate.hpp"

namespace swarmcheck::dse {

class Journal {
 public:
  // Opens (creating) the journal and reads what is there. Later lines for a key win.
  explicit Journal(std::string path);
  ~Journal();
  Journal(const Journal&) = delete;
  Journal& operator=(const Journal&) = delete;

  const PointRuns* find(const std::string& key) const;
  // In the file when it returns (durable within kSyncInterval). Not thread-safe: the sweep calls
  // it from one thread at a time.
  void append(const PointRuns& p, const std::string& label);
  void sync();   // durable now

  static constexpr std::chrono::milliseconds kSyncInterval{50};

  std::size_t entries() const { return entries_.size(); }
  std::size_t skipped_lines() const { return skipped_; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  int fd_ = -1;
  std::map<std::string, PointRuns> entries_;
  std::size_t skipped_ = 0;
  std::chrono::steady_clock::time_point last_sync_{};
  bool dirty_ = false;
};

}  // namespace swarmcheck::dse
