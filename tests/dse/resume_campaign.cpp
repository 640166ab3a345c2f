#include "tests/dse/resume_campaign.hpp"

#include <rapidcheck.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "conformance/common/campaign.hpp"
#include "impl/dse/results_io.hpp"
#include "impl/dse/sweep.hpp"
#include "spec/exploration/scenario.hpp"

namespace swarmcheck::testing::dse {
namespace {

namespace fs = std::filesystem;
using namespace swarmcheck::dse;
using json_io::Json;

// A small exhaustive sweep: a few points of a few short runs each.
struct Sweep {
  std::string config_text;
  int map_size = 6;
};

Sweep gen_sweep() {
  const auto pick = [](std::vector<std::string> pool, std::size_t n) {
    std::vector<std::string> out;
    for (std::size_t k = 0; k < n && !pool.empty(); ++k) {
      const auto at = *rc::gen::inRange<std::size_t>(0, pool.size());
      out.push_back(pool[at]);
      pool.erase(pool.begin() + static_cast<std::ptrdiff_t>(at));
    }
    return out;
  };
  const auto list = [](const std::vector<std::string>& v) {
    std::string s = "[";
    for (const auto& x : v) s += (s.size() > 1 ? ", " : "") + x;
    return s + "]";
  };
  const std::vector<std::string> ertu = pick({"0.01", "0.05", "0.1", "0.2"}, *rc::gen::inRange<std::size_t>(1, 4));
  const std::vector<std::string> rule = pick({"\"deterministic\"", "\"stochastic\""}, *rc::gen::inRange<std::size_t>(1, 3));
  const std::vector<std::string> robots = pick({"2", "3"}, *rc::gen::inRange<std::size_t>(1, 3));
  const int replicates = *rc::gen::inRange(1, 3);
  Sweep s;
  s.map_size = *rc::gen::inRange(5, 9);
  s.config_text = R"({"algorithm": {"type": "exhaustive"}, "parameters": {"ertu": )" + list(ertu) + R"(, "rule": )" +
                  list(rule) + R"(, "nRobots": )" + list(robots) + R"(, "replicates": [)" + std::to_string(replicates) +
                  R"(]}, "objectiveDefinitions": {"internalFunctions": {
                       "e": {"columnID": "eP", "objectiveType": "mean"},
                       "t": {"columnID": "completion_step", "objectiveType": "max"},
                       "d": {"columnID": "distance", "objectiveType": "max"}}},
                     "ranking": {"pareto": {"e": "+", "t": "-"}}})";
  return s;
}

struct Swept {
  SweepOutcome outcome;
  std::string results;   // results.json's and results.csv's text
};

Swept sweep(const DesignSpace& space, const fs::path& journal) {
  ThreadExecutor threads(space, needed_columns(space.config()), 1, nullptr);
  Swept s;
  s.outcome = run_sweep(space, threads, SweepOptions{journal.string(), nullptr, nullptr});
  DseResults r = rank_outcomes(space, s.outcome.points);
  r.generations = s.outcome.generations;
  s.results = results_json(space, r, ResultsContext{"resume.dse.json", "base"}).dump(1) + "\n" + results_csv(space, r);
  return s;
}

std::vector<std::string> lines_of(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) out.push_back(line);
  return out;
}

// A line for the same point with other runs: as if the point had been computed before with
// other results (the first run of a step count and an eP mean changed).
std::string older_line(const std::string& line, int64_t delta) {
  Json j = Json::parse(line);
  Json& run = j["runs"][0];
  run["steps"] = run["steps"].get<int64_t>() + delta;
  Json& ep = run["columns"]["eP"];
  ep[2] = ep[2].get<double>() + static_cast<double>(delta) * 0.5;
  return j.dump();
}

// One journal line as written into the resumed sweep's journal.
struct Entry {
  std::string text;
  std::size_t point = 0;   // which point's line it is made from
  // last: the point's final line (what the uninterrupted sweep wrote); copy: the same again;
  // older: the point with other runs, before its final line; cut: a prefix; foreign: another key
  enum Kind { last, copy, older, cut, foreign } kind = last;
};

// The resumed journal: per point of the uninterrupted one, its fate; then any order in which each
// point's final line comes after its older lines.
struct ResumedJournal {
  std::vector<Entry> entries;
  bool last_without_newline = false;
  std::vector<char> computed;   // per point: no final line, so the sweep must compute it
};

ResumedJournal gen_journal(const std::vector<std::string>& lines) {
  ResumedJournal j;
  j.computed.assign(lines.size(), 0);
  for (std::size_t p = 0; p < lines.size(); ++p) {
    const bool missing = *rc::gen::inRange(0, 5) == 0;
    j.computed[p] = missing ? 1 : 0;
    if (!missing) {   // older lines and copies only where the final line was written
      j.entries.push_back(Entry{lines[p], p, Entry::last});
      const int older = *rc::gen::inRange(0, 3);
      for (int k = 0; k < older; ++k) j.entries.push_back(Entry{older_line(lines[p], k + 1), p, Entry::older});
      if (*rc::gen::inRange(0, 4) == 0) j.entries.push_back(Entry{lines[p], p, Entry::copy});
    }
    if (*rc::gen::inRange(0, 3) == 0) {
      const auto at = *rc::gen::inRange<std::size_t>(1, lines[p].size());
      j.entries.push_back(Entry{lines[p].substr(0, at), p, Entry::cut});
    }
  }
  if (*rc::gen::inRange(0, 4) == 0 && !lines.empty()) {   // a line of another sweep's point
    Json other = Json::parse(lines.front());
    other["key"] = "0123456789abcdef";
    j.entries.push_back(Entry{other.dump(), 0, Entry::foreign});
  }
  // Any order, then each point's final line moved behind its older lines (the last line wins).
  for (std::size_t k = j.entries.size(); k > 1; --k)
    std::swap(j.entries[k - 1], j.entries[*rc::gen::inRange<std::size_t>(0, k)]);
  for (std::size_t p = 0; p < lines.size(); ++p) {
    std::size_t final_at = j.entries.size(), last_older = 0;
    bool has_older = false;
    for (std::size_t k = 0; k < j.entries.size(); ++k) {
      if (j.entries[k].point != p || j.entries[k].kind == Entry::foreign) continue;
      if (j.entries[k].kind == Entry::last) final_at = k;
      if (j.entries[k].kind == Entry::older) {
        has_older = true;
        last_older = k;
      }
    }
    if (final_at < j.entries.size() && has_older && last_older > final_at) std::swap(j.entries[final_at], j.entries[last_older]);
  }
  j.last_without_newline = !j.entries.empty() && j.entries.back().kind == Entry::cut && *rc::gen::arbitrary<bool>();
  return j;
}

void write_journal(const fs::path& path, const ResumedJournal& j) {
  std::ofstream out(path, std::ios::binary);
  for (std::size_t k = 0; k < j.entries.size(); ++k) {
    out << j.entries[k].text;
    if (k + 1 < j.entries.size() || !j.last_without_newline) out << '\n';
  }
}

// The first line where two texts differ, both sides.
std::string first_difference(const std::string& want, const std::string& got) {
  std::istringstream a(want), b(got);
  std::string la, lb;
  for (int line = 1;; ++line) {
    const bool ma = static_cast<bool>(std::getline(a, la)), mb = static_cast<bool>(std::getline(b, lb));
    if (!ma && !mb) return "";
    if (!ma || !mb || la != lb)
      return "results line " + std::to_string(line) + ": uninterrupted `" + (ma ? la : "(end)") + "`, resumed `" +
             (mb ? lb : "(end)") + "`";
  }
}

}  // namespace

ResumeReport run_resume_campaign(uint64_t seed, int cases, const std::string& out_dir) {
  ResumeReport report;
  const fs::path scratch = fs::temp_directory_path() / ("swarmcheck-resume-" + std::to_string(::getpid()));
  struct Failure {
    std::string difference, config_text;
    ResumedJournal journal;
  };
  std::optional<Failure> last_failure;   // the last is the smallest
  int case_no = 0;
  const auto property = [&] {
    const Sweep s = gen_sweep();
    const DseConfig config = parse_dse_config(s.config_text, "resume.dse.json");
    exploration::Scenario base = exploration::default_scenario();
    base.mode = exploration::Mode::abstract;
    base.map_size = s.map_size;
    base.robots = {{0.5, 0.5}, {base.map_size - 0.5, 0.5}};
    base.obstacles.clear();
    base.max_steps = 40;
    const DesignSpace space(config, base);
    check_design_space(space);
    const fs::path dir = scratch / std::to_string(case_no++);
    fs::remove_all(dir);
    fs::create_directories(dir / "whole");
    fs::create_directories(dir / "resumed");
    const Swept whole = sweep(space, dir / "whole" / "journal.jsonl");
    const ResumedJournal journal = gen_journal(lines_of(dir / "whole" / "journal.jsonl"));
    write_journal(dir / "resumed" / "journal.jsonl", journal);
    const Swept resumed = sweep(space, dir / "resumed" / "journal.jsonl");
    fs::remove_all(dir);
    std::string difference = first_difference(whole.results, resumed.results);
    const auto to_compute = static_cast<std::size_t>(std::count(journal.computed.begin(), journal.computed.end(), 1));
    if (difference.empty() && resumed.outcome.computed != to_compute)
      difference = "the resumed sweep computed " + std::to_string(resumed.outcome.computed) + " points, not the " +
                   std::to_string(to_compute) + " whose final line is missing or cut";
    if (!difference.empty()) {
      last_failure = Failure{difference, s.config_text, journal};
    } else if (!last_failure) {
      report.points_resumed += static_cast<int>(resumed.outcome.from_journal);
      for (const Entry& e : journal.entries) {
        report.repeated_points += e.kind == Entry::older ? 1 : 0;
        report.cut_lines += e.kind == Entry::cut ? 1 : 0;
      }
    }
    RC_ASSERT(difference.empty());
  };
  const conformance::CampaignRun run = conformance::run_campaign("dse: a resumed sweep gives the uninterrupted results",
                                                                 seed, cases, property);
  std::error_code ignored;
  fs::remove_all(scratch, ignored);
  report.cases_run = run.cases_run;
  if (!last_failure) return report;
  ResumeCounterexample cx;
  cx.difference = last_failure->difference;
  cx.config_text = last_failure->config_text;
  cx.shrinks = run.shrinks;
  cx.journal_lines = static_cast<int>(last_failure->journal.entries.size());
  fs::create_directories(out_dir);
  cx.journal_path = (fs::path(out_dir) / ("resume-seed" + std::to_string(seed) + "-journal.jsonl")).string();
  write_journal(cx.journal_path, last_failure->journal);
  std::ofstream(fs::path(out_dir) / ("resume-seed" + std::to_string(seed) + ".dse.json")) << cx.config_text << "\n";
  report.counterexample = cx;
  return report;
}

}  // namespace swarmcheck::testing::dse
