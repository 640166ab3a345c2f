#pragma once
// The DSE resume property, as a seeded campaign (conformance/common/campaign.hpp): a sweep resumed
// from any journal gives the results of the same sweep run uninterrupted. Each case draws a small
// exhaustive sweep (1..3 ertu values, one or two rule sets and robot counts, 1..2 replicates, on a
// small map), runs it uninterrupted, then writes a journal made from the uninterrupted one's lines:
//   - points missing (the sweep was cut before them), and lines cut anywhere (a crash mid-write),
//     the last line possibly without its newline;
//   - points repeated: copies of a line, and older lines for the same point with other runs (a
//     point recomputed after its first line was written: the journal's rule is that the last line
//     for a point wins), always before the point's final line;
//   - lines of points of another sweep (other keys);
//   - the lines in any order (the threads finish points in any order).
// The resumed sweep must give the uninterrupted results byte for byte (results.json's and
// results.csv's text), and compute exactly the points whose final line is missing or cut.
// A failure shrinks (RapidCheck) and its journal is written to `out_dir`.
#include <cstdint>
#include <optional>
#include <string>

namespace swarmcheck::testing::dse {

struct ResumeCounterexample {
  std::string difference;     // what differs, first
  std::string journal_path;   // the minimal journal, as the resumed sweep read it
  std::string config_text;    // the sweep's configuration (JSON)
  int journal_lines = 0;
  int shrinks = 0;
};

struct ResumeReport {
  int cases_run = 0;
  int points_resumed = 0;           // points read from a journal, in the cases before a failure
  int repeated_points = 0;          // ... of which had older lines with other runs
  int cut_lines = 0;                // lines cut mid-write
  std::optional<ResumeCounterexample> counterexample;
};

inline constexpr int kResumeCases = 40;

ResumeReport run_resume_campaign(uint64_t seed, int cases, const std::string& out_dir);

}  // namespace swarmcheck::testing::dse
