#pragma once
// The mutation test's harness: the commands run on each mutant, the contract checked on every
// run (status, message, input and output files, the folder), and the report of what broke,
// grouped by class, with each failing input saved and the command to run it again.
#include <gtest/gtest.h>
#include <strings.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "tests/hardening/mutation/mutants.hpp"
#include "tests/hardening/mutation/process.hpp"
#include "tests/hardening/mutation/text.hpp"

namespace swarmcheck::testing::mutation {

namespace fs = std::filesystem;

struct Command {
  std::string name;
  // The arguments, given the input path and the output path (the output is created beforehand
  // with known bytes when `writes` is true).
  std::function<std::vector<std::string>(const std::string& in, const std::string& out)> args;
  bool writes = false;
};

struct Failure {
  std::string group, what, command, detail;
};

inline std::uint64_t seed_for(std::uint64_t fixed) {
  const char* s = std::getenv("SWARMCHECK_MUTATION_SEED");
  return s ? std::strtoull(s, nullptr, 10) ^ fixed : fixed;
}

inline std::size_t count_for(std::size_t fixed) {
  const char* s = std::getenv("SWARMCHECK_MUTATIONS");
  return s ? std::strtoul(s, nullptr, 10) : fixed;
}

inline std::string joined(const std::vector<std::string>& args) {
  std::string r = "swarmcheck";
  for (const auto& a : args) r += " " + a;
  return r;
}

// What went wrong with one run: a class (failures are grouped by it) and the particulars.
struct Problem {
  std::string kind, detail;
};

inline bool names_inf_or_nan(const std::string& out) {
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (i > 0 && std::isalnum(static_cast<unsigned char>(out[i - 1]))) continue;
    for (const char* w : {"inf", "nan", "-nan", "infinity"}) {
      const std::size_t n = std::strlen(w);
      if (out.size() - i >= n && strncasecmp(out.c_str() + i, w, n) == 0 &&
          (i + n == out.size() || !std::isalnum(static_cast<unsigned char>(out[i + n]))))
        return true;
    }
  }
  return false;
}

// Status 2's message: one line on stderr, "swarmcheck: error: FILE:" then where and what, short
// (not counting the path, which is as long as the caller made it) and printable.
inline void check_message(const Outcome& o, const fs::path& input, std::vector<Problem>& p) {
  const std::string& e = o.err;
  const std::string name = input.filename().string();
  const std::size_t newlines = static_cast<std::size_t>(std::count(e.begin(), e.end(), '\n'));
  const std::size_t all_lines = newlines + static_cast<std::size_t>(std::count(o.out.begin(), o.out.end(), '\n'));
  std::size_t longest = 0;
  for (const std::string* s : {&o.out, &o.err})
    for (const Line& l : lines_of(*s)) {
      std::string line = s->substr(l.begin, l.end - l.begin);
      const std::size_t at = line.find(input.string());
      if (at != std::string::npos) line.erase(at, input.string().size());
      longest = std::max(longest, line.size());
    }
  if (e.empty())
    p.push_back({"status 2 with nothing on stderr", ""});
  else if (newlines != 1 || e.back() != '\n')
    p.push_back({"stderr is not one line", std::to_string(newlines) + " newlines"});
  if (all_lines > 3) p.push_back({"more than 3 lines of output", std::to_string(all_lines) + " lines"});
  if (longest > 400)
    p.push_back({"a message line over 400 bytes (path not counted)", std::to_string(longest) + " bytes"});
  if (!e.empty() && e.rfind("swarmcheck: error: ", 0) != 0)
    p.push_back({"stderr does not start with 'swarmcheck: error: '", ""});
  const std::size_t at = e.find(name);
  if (at == std::string::npos)
    p.push_back({"the message does not name the file", name});
  else if (at + name.size() >= e.size() || e[at + name.size()] != ':')
    p.push_back({"the file name is not followed by ':' and a position", ""});
  std::string body = e;
  if (!body.empty() && body.back() == '\n') body.pop_back();
  const bool control =
      std::any_of(body.begin(), body.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; });
  if (control || !valid_utf8(body)) p.push_back({"the message echoes raw control bytes or invalid UTF-8", ""});
}

// The problems with one run of a command on a mutant; empty when the contract holds.
inline std::vector<Problem> problems(const Mutant& m, const Outcome& o, int original_status, const fs::path& input,
                                     const std::string& input_before, const fs::path& output, bool writes,
                                     const fs::path& dir, const std::set<std::string>& expected_files) {
  std::vector<Problem> p;
  const bool exited = !o.timed_out && o.signal == 0;
  if (o.timed_out)
    p.push_back({"no answer within the time limit (killed)", ""});
  else if (o.signal != 0)
    p.push_back({"killed by signal " + std::to_string(o.signal) + " (" + strsignal(o.signal) + ")", ""});
  else if (o.status < 0 || o.status > 2)
    p.push_back({"exit status " + std::to_string(o.status) + " (want 0, 1 or 2)", ""});
  else if (m.bad && o.status != 2)
    p.push_back({"a bad input accepted with status " + std::to_string(o.status), ""});
  else if (m.same && o.status != original_status)
    p.push_back({"an equivalent input gives another status",
                 std::to_string(o.status) + ", the original gives " + std::to_string(original_status)});
  if (exited && o.status == 2) check_message(o, input, p);
  if (exited && (o.status == 0 || o.status == 1) && names_inf_or_nan(o.out))
    p.push_back({"a result printed as inf or nan (an overflow accepted)", ""});
  if (read_bytes(input) != input_before) p.push_back({"the input file was modified", ""});
  if (writes && !(exited && (o.status == 0 || o.status == 1)) && read_bytes(output) != kPreexisting)
    p.push_back({"the pre-existing output changed although the command failed",
                 fs::exists(output) ? std::to_string(fs::file_size(output)) + " bytes now" : "removed"});
  const std::set<std::string> now = listing(dir);
  for (const auto& f : now)
    if (!expected_files.count(f)) p.push_back({"a stray file is left in the folder", f});
  for (const auto& f : expected_files)
    if (!now.count(f)) p.push_back({"a file of the folder is gone", f});
  return p;
}

class MutationHarness {
 public:
  explicit MutationHarness(const std::string& test) : test_(test) {
    dir_ = fs::temp_directory_path() / ("swarmcheck-mutation-" + std::to_string(::getpid())) / test;
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    fs::remove_all(saved_dir());  // only this run's failures
  }
  ~MutationHarness() {
    // Failing inputs are already copied to saved_dir().
    std::error_code ec;
    fs::remove_all(dir_, ec);
    fs::remove(dir_.parent_path(), ec);  // when it is empty
  }
  const fs::path& dir() const { return dir_; }
  // A file the commands need beside the input (a mission's .fsm); it must stay as it is.
  void fixture(const fs::path& from) {
    fs::copy_file(from, dir_ / from.filename(), fs::copy_options::overwrite_existing);
    fixtures_.push_back(from);
  }

  // Runs every command on the original, then on every mutant.
  void check(const std::string& base_name, const std::string& original, const std::vector<Mutant>& mutants,
             const std::vector<Command>& commands) {
    const fs::path out = dir_ / "out.preexisting";
    std::map<std::string, int> original_status;
    for (const Command& c : commands) {
      const fs::path in = dir_ / base_name;
      write_bytes(in, original);
      write_bytes(out, kPreexisting);
      const auto args = c.args(in.string(), out.string());
      const Outcome o = run_swarmcheck(args, kLimit);
      ASSERT_TRUE(o.status == 0 || o.status == 1)
          << joined(args) << " on the unmutated file: status " << o.status << " signal " << o.signal << "\n"
          << o.out << o.err;
      original_status[c.name] = o.status;
      fs::remove(in);
    }
    for (std::size_t i = 0; i < mutants.size(); ++i) {
      const Mutant& m = mutants[i];
      // The mutant's own name, so the message can be seen to name it.
      const std::string name = "m" + std::to_string(i) + "-" + base_name;
      const fs::path in = dir_ / name;
      write_bytes(in, m.text);
      for (const Command& c : commands) {
        write_bytes(out, kPreexisting);
        const std::set<std::string> expected = listing(dir_);
        const auto args = c.args(in.string(), out.string());
        const Outcome o = run_swarmcheck(args, kLimit);
        ++runs_;
        ++per_op_[m.op];
        if (std::getenv("SWARMCHECK_MUTATION_VERBOSE"))
          std::printf("#%zu %s | %s | status %d signal %d | %s | %s\n", i, m.op.c_str(), c.name.c_str(), o.status,
                      o.signal, m.what.c_str(), shown(o.err.empty() ? o.out : o.err, 160).c_str());
        const auto p = problems(m, o, original_status[c.name], in, m.text, out, c.writes, dir_, expected);
        if (!p.empty()) {
          record(m, i, name, c, args, o, p);
          ++failed_runs_;
        }
        // Put the folder back for the next run whatever happened.
        for (const auto& f : listing(dir_))
          if (!expected.count(f)) fs::remove_all(dir_ / f);
        if (read_bytes(in) != m.text) write_bytes(in, m.text);
      }
      fs::remove(in);
    }
  }

  void report() {
    std::ostringstream s;
    s << test_ << ": " << runs_ << " runs;";
    for (const auto& [op, n] : per_op_) s << " " << op << " " << n;
    std::printf("%s\n", s.str().c_str());
    if (failures_.empty()) return;
    std::map<std::string, std::vector<const Failure*>> by_group;
    for (const Failure& f : failures_) by_group[f.group].push_back(&f);
    std::ostringstream r;
    r << failed_runs_ << " of " << runs_ << " runs broke the contract, in " << by_group.size()
      << " classes (mutation | command | what broke). Mutated inputs are saved in " << saved_dir().string() << "\n";
    for (const auto& [group, list] : by_group) {
      r << "\n== " << group << ": " << list.size() << " runs\n";
      for (std::size_t k = 0; k < list.size() && k < 2; ++k) {
        const Failure& f = *list[k];
        r << "  - " << f.what << "\n    $ " << f.command << "\n    " << f.detail << "\n";
      }
    }
    ADD_FAILURE() << r.str();
  }

 private:
  static constexpr std::chrono::milliseconds kLimit{10000};

  fs::path saved_dir() const { return fs::temp_directory_path() / "swarmcheck-mutation-failures" / test_; }

  void record(const Mutant& m, std::size_t i, const std::string& name, const Command& c,
              const std::vector<std::string>& args, const Outcome& o, const std::vector<Problem>& p) {
    const fs::path saved = saved_dir() / name;
    fs::create_directories(saved_dir());
    write_bytes(saved, m.text);
    for (const auto& f : fixtures_) fs::copy_file(f, saved_dir() / f.filename(), fs::copy_options::overwrite_existing);
    if (c.writes) write_bytes(saved_dir() / "out.preexisting", kPreexisting);
    std::vector<std::string> shown_args;
    for (const auto& a : args) {
      if (a == (dir_ / name).string())
        shown_args.push_back(saved.string());
      else if (a == (dir_ / "out.preexisting").string())
        shown_args.push_back((saved_dir() / "out.preexisting").string());
      else
        shown_args.push_back(a);
    }
    std::string detail = "status " + std::to_string(o.status);
    if (o.signal) detail += ", signal " + std::to_string(o.signal);
    if (o.timed_out) detail += ", timed out";
    for (const auto& x : p) detail += "; " + x.kind + (x.detail.empty() ? "" : " (" + x.detail + ")");
    detail += "\n    stderr: " + shown(o.err, 300);
    if (!o.out.empty()) detail += "\n    stdout: " + shown(o.out, 200);
    const std::string what = "#" + std::to_string(i) + " " + m.what +
                             (m.bad    ? " [bad]"
                              : m.same ? " [equivalent]"
                                       : "");
    // One entry per class of problem, so each class is listed with its own examples.
    std::set<std::string> kinds;
    for (const auto& x : p) kinds.insert(x.kind);
    for (const auto& kind : kinds)
      failures_.push_back({m.op + " | " + c.name + " | " + kind, what, joined(shown_args), detail});
  }

  std::string test_;
  fs::path dir_;
  std::vector<fs::path> fixtures_;
  std::vector<Failure> failures_;
  std::size_t runs_ = 0, failed_runs_ = 0;
  std::map<std::string, std::size_t> per_op_;
};

}  // namespace swarmcheck::testing::mutation
