// Hardening by mutation, from the outside: a few hundred bad inputs made from the shipped files
// (a fixed seed, so every run makes the same ones), each run through the binary. The contract of
// README "The command line": bad input of any kind gets exit status 2 and one short message
// naming the file and where (line:col or JSON path); never status 3 ("internal error"), a signal
// or a hang. An odd input that is still valid may give 0 or 1. No input file is changed, and a
// failed command leaves a pre-existing output file with its exact bytes and no temp file beside
// it.
//
// A failure names the mutation class and what was changed, saves the mutated input under
// $TMPDIR/swarmcheck-mutation-failures/ and prints the command to run it again.
// SWARMCHECK_MUTATION_SEED and SWARMCHECK_MUTATIONS (mutants per shipped file) change the set;
// SWARMCHECK_MUTATION_VERBOSE=1 prints every run.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <strings.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

const std::string kBin = SWARMCHECK_BIN;
const std::string kSource = SWARMCHECK_SOURCE_DIR;
const std::string kPreexisting = "PRE-EXISTING OUTPUT: these bytes must survive a failed command\n";

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

// ---------------------------------------------------------------------------------------------
// Running the binary. tests/util/shell.hpp's run_binary goes through popen: it has no time limit
// and WEXITSTATUS of a process killed by a signal reads as 0. This one forks and execs directly
// (no shell quoting), keeps stdout and stderr apart, kills the process group at the deadline,
// reports a signal as a signal, and caps the address space (2 GiB by default; under
// AddressSanitizer, which needs a huge address space, the resident set instead) so an input that
// makes the binary allocate without bound ends as bad_alloc (status 3) instead of waking the OOM
// killer.

struct Outcome {
  int status = -1;  // exit status when the process exited
  int signal = 0;   // the signal when it was killed by one
  bool timed_out = false;
  std::string out, err;
};

Outcome run_swarmcheck(const std::vector<std::string>& args, std::chrono::milliseconds limit,
                       std::size_t memory_mib = 2048) {
  int out_pipe[2], err_pipe[2];
  if (::pipe2(out_pipe, O_CLOEXEC) != 0 || ::pipe2(err_pipe, O_CLOEXEC) != 0) {
    ADD_FAILURE() << "pipe2: " << std::strerror(errno);
    return {};
  }
  std::vector<std::string> argv_s{kBin};
  argv_s.insert(argv_s.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argv_s) argv.push_back(a.data());
  argv.push_back(nullptr);
  // A sanitizer's report exits 1 by default, which reads as a verdict here: make it 99.
  auto options = [](const char* name, const std::string& more) {
    const char* old = std::getenv(name);
    return std::string(old ? old : "") + (old && *old ? ":" : "") + more;
  };
  const std::string asan_options =
      options("ASAN_OPTIONS",
              "exitcode=99" + (kAddressSanitizer ? ":hard_rss_limit_mb=" + std::to_string(memory_mib) : std::string()));
  const std::string ubsan_options = options("UBSAN_OPTIONS", "halt_on_error=1:exitcode=99");
  std::vector<std::string> env_s{"ASAN_OPTIONS=" + asan_options, "UBSAN_OPTIONS=" + ubsan_options};
  for (char** e = environ; *e; ++e)
    if (std::strncmp(*e, "ASAN_OPTIONS=", 13) != 0 && std::strncmp(*e, "UBSAN_OPTIONS=", 14) != 0)
      env_s.emplace_back(*e);
  std::vector<char*> envp;
  for (auto& e : env_s) envp.push_back(e.data());
  envp.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::setpgid(0, 0);
    const int null_in = ::open("/dev/null", O_RDONLY);
    ::dup2(null_in, 0);
    ::dup2(out_pipe[1], 1);
    ::dup2(err_pipe[1], 2);
    rlimit core{0, 0};
    ::setrlimit(RLIMIT_CORE, &core);
    if (!kAddressSanitizer) {
      const rlim_t cap = rlim_t{memory_mib} << 20;
      rlimit as{cap, cap};
      ::setrlimit(RLIMIT_AS, &as);
    }
    ::execve(argv[0], argv.data(), envp.data());
    ::_exit(127);
  }
  ::setpgid(pid, pid);  // also from here, so the kill below reaches it even before the child runs
  ::close(out_pipe[1]);
  ::close(err_pipe[1]);
  Outcome o;
  const auto deadline = std::chrono::steady_clock::now() + limit;
  pollfd fds[2] = {{out_pipe[0], POLLIN, 0}, {err_pipe[0], POLLIN, 0}};
  std::string* sinks[2] = {&o.out, &o.err};
  int open_fds = 2;
  bool killed = false;
  while (open_fds > 0) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0 && !killed) {
      ::kill(-pid, SIGKILL);
      killed = true;
      o.timed_out = true;
    }
    const int n = ::poll(fds, 2, killed ? 1000 : static_cast<int>(std::max<long long>(1, left.count())));
    if (n < 0 && errno == EINTR) continue;
    if (n == 0 && killed) break;  // a grandchild holds the pipe; give up on it
    for (int i = 0; i < 2; ++i) {
      if (fds[i].fd < 0 || fds[i].revents == 0) continue;
      char buf[8192];
      const ssize_t got = ::read(fds[i].fd, buf, sizeof buf);
      if (got > 0) {
        if (sinks[i]->size() < (1u << 20)) sinks[i]->append(buf, static_cast<std::size_t>(got));
      } else if (got == 0 || errno != EINTR) {
        ::close(fds[i].fd);
        fds[i].fd = -1;
        --open_fds;
      }
    }
  }
  for (auto& f : fds)
    if (f.fd >= 0) ::close(f.fd);
  int ws = 0;
  if (!killed && ::waitpid(pid, &ws, WNOHANG) == 0) {
    // Both pipes closed but the process is still there (it closed them itself): wait out the rest.
    while (::waitpid(pid, &ws, WNOHANG) == 0) {
      if (std::chrono::steady_clock::now() > deadline) {
        ::kill(-pid, SIGKILL);
        o.timed_out = true;
        ::waitpid(pid, &ws, 0);
        break;
      }
      ::usleep(1000);
    }
  } else if (killed) {
    ::waitpid(pid, &ws, 0);
  }
  if (WIFEXITED(ws)) o.status = WEXITSTATUS(ws);
  if (WIFSIGNALED(ws)) o.signal = WTERMSIG(ws);
  return o;
}

// ---------------------------------------------------------------------------------------------
// Files and text.

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void write_bytes(const fs::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary | std::ios::trunc) << bytes;
}

std::set<std::string> listing(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

// Bytes as a reader can see them in a terminal: control and non-ASCII bytes escaped, cut at max.
std::string shown(const std::string& s, std::size_t max = 160) {
  std::string r;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (r.size() >= max) {
      r += "...(" + std::to_string(s.size()) + " bytes)";
      break;
    }
    const auto c = static_cast<unsigned char>(s[i]);
    if (c == '\n')
      r += "\\n";
    else if (c == '\t')
      r += "\\t";
    else if (c == '\\')
      r += "\\\\";
    else if (c < 0x20 || c >= 0x7f) {
      char b[8];
      std::snprintf(b, sizeof b, "\\x%02x", c);
      r += b;
    } else
      r += static_cast<char>(c);
  }
  return r;
}

bool valid_utf8(const std::string& s) {
  std::size_t i = 0;
  while (i < s.size()) {
    const auto c = static_cast<unsigned char>(s[i]);
    std::size_t n = 0;
    std::uint32_t cp = 0;
    if (c < 0x80) {
      ++i;
      continue;
    } else if ((c & 0xE0) == 0xC0) {
      n = 1, cp = c & 0x1F;
    } else if ((c & 0xF0) == 0xE0) {
      n = 2, cp = c & 0x0F;
    } else if ((c & 0xF8) == 0xF0) {
      n = 3, cp = c & 0x07;
    } else {
      return false;
    }
    if (i + n >= s.size()) return false;
    for (std::size_t k = 1; k <= n; ++k) {
      const auto d = static_cast<unsigned char>(s[i + k]);
      if ((d & 0xC0) != 0x80) return false;
      cp = (cp << 6) | (d & 0x3F);
    }
    if ((n == 1 && cp < 0x80) || (n == 2 && cp < 0x800) || (n == 3 && cp < 0x10000) || cp > 0x10FFFF ||
        (cp >= 0xD800 && cp <= 0xDFFF))
      return false;
    i += n + 1;
  }
  return true;
}

std::string line_col(const std::string& text, std::size_t pos) {
  std::size_t line = 1, col = 1;
  for (std::size_t i = 0; i < pos && i < text.size(); ++i) {
    if (text[i] == '\n')
      ++line, col = 1;
    else
      ++col;
  }
  return std::to_string(line) + ":" + std::to_string(col);
}

struct Line {
  std::size_t begin, end;  // [begin, end) without the '\n'
};

std::vector<Line> lines_of(const std::string& text) {
  std::vector<Line> lines;
  std::size_t b = 0;
  while (b < text.size()) {
    std::size_t e = text.find('\n', b);
    if (e == std::string::npos) e = text.size();
    lines.push_back({b, e});
    b = e + 1;
  }
  return lines;
}

bool blank(const std::string& text, const Line& l) {
  for (std::size_t i = l.begin; i < l.end; ++i)
    if (!std::isspace(static_cast<unsigned char>(text[i]))) return false;
  return true;
}

// ---------------------------------------------------------------------------------------------
// Mutants.

struct Mutant {
  std::string op;     // the mutation class
  std::string what;   // where and what changed, for the failure message
  std::string text;   // the mutated file
  bool bad = false;   // certainly invalid: must give status 2
  bool same = false;  // equivalent to the original: must give the original's status
};

using Rng = std::mt19937_64;

std::size_t below(Rng& rng, std::size_t n) {
  return n == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
}

template <class T>
const T& pick(Rng& rng, const std::vector<T>& v) {
  return v[below(rng, v.size())];
}

const std::string kFiftyDigits = "12345678901234567890123456789012345678901234567890";
const std::vector<std::string> kInvalidUtf8 = {
    "\xff", "\xc3", "\x80", "\xed\xa0\x80", "\xc0\xaf", "\xf8\x88\x80\x80\x80", "\xe2\x82"};

Mutant replace(const std::string& op, const std::string& text, std::size_t b, std::size_t e, const std::string& with,
               const std::string& where) {
  Mutant m;
  m.op = op;
  m.text = text.substr(0, b) + with + text.substr(e);
  m.what = line_col(text, b) + where + ": '" + shown(text.substr(b, e - b), 60) + "' -> '" + shown(with, 60) + "'";
  return m;
}

Mutant byte_flip(Rng& rng, const std::string& text) {
  const std::size_t pos = below(rng, text.size());
  const int bit = static_cast<int>(below(rng, 8));
  std::string t = text;
  t[pos] = static_cast<char>(static_cast<unsigned char>(t[pos]) ^ (1u << bit));
  Mutant m = replace("byte_flip", text, pos, pos + 1, t.substr(pos, 1), " bit " + std::to_string(bit));
  return m;
}

Mutant truncation(Rng& rng, const std::string& text, std::size_t keep_below) {
  const std::size_t cut = below(rng, keep_below);
  Mutant m;
  m.op = "truncate";
  m.text = text.substr(0, cut);
  m.what = "cut at byte " + std::to_string(cut) + " (" + line_col(text, cut) + ") of " + std::to_string(text.size()) +
           ", last bytes kept '" + shown(text.substr(cut >= 30 ? cut - 30 : 0, std::min<std::size_t>(cut, 30))) + "'";
  return m;
}

Mutant delete_line(const std::string& text, const std::vector<Line>& lines, std::size_t i) {
  Mutant m;
  m.op = "delete_line";
  const std::size_t end = std::min(text.size(), lines[i].end + 1);
  m.text = text.substr(0, lines[i].begin) + text.substr(end);
  m.what = "line " + std::to_string(i + 1) + " '" +
           shown(text.substr(lines[i].begin, lines[i].end - lines[i].begin), 80) + "' deleted";
  return m;
}

Mutant duplicate_line(const std::string& text, const std::vector<Line>& lines, std::size_t i) {
  Mutant m;
  m.op = "duplicate_line";
  const std::string line = text.substr(lines[i].begin, lines[i].end - lines[i].begin) + "\n";
  m.text = text.substr(0, lines[i].begin) + line + text.substr(lines[i].begin);
  m.what = "line " + std::to_string(i + 1) + " '" + shown(line, 80) + "' twice";
  return m;
}

// JSON text as tokens, with the JSON path of every key and value, so a mutation can change one
// value in place and keep the rest of the file byte for byte. Lenient: it reads the shipped
// (valid) files only. For JSON Lines each line is one top-level value, `root` its 0-based line.
struct JTok {
  enum Kind { Str, Num, Lit, Open, Close, Colon, Comma } kind;
  std::size_t b, e;  // the token's bytes; for Open, e is the end of its matching Close
  bool key = false;
  std::string path = {};  // of the value (or of the member, for a key)
  std::size_t root = 0;
};

JTok jtok(JTok::Kind kind, std::size_t b, std::size_t e) {
  JTok t{kind, b, e};
  return t;
}

std::vector<JTok> json_tokens(const std::string& s) {
  std::vector<JTok> toks;
  std::size_t i = 0;
  while (i < s.size()) {
    const char c = s[i];
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
    } else if (c == '{' || c == '[') {
      toks.push_back(jtok(JTok::Open, i, i + 1));
      ++i;
    } else if (c == '}' || c == ']') {
      toks.push_back(jtok(JTok::Close, i, i + 1));
      ++i;
    } else if (c == ':') {
      toks.push_back(jtok(JTok::Colon, i, i + 1));
      ++i;
    } else if (c == ',') {
      toks.push_back(jtok(JTok::Comma, i, i + 1));
      ++i;
    } else if (c == '"') {
      std::size_t j = i + 1;
      while (j < s.size() && s[j] != '"') j += s[j] == '\\' ? 2 : 1;
      toks.push_back(jtok(JTok::Str, i, j + 1));
      i = j + 1;
    } else if (c == '-' || std::isdigit(static_cast<unsigned char>(c))) {
      std::size_t j = i + 1;
      while (j < s.size() && (std::isdigit(static_cast<unsigned char>(s[j])) || std::strchr("+-.eE", s[j]))) ++j;
      toks.push_back(jtok(JTok::Num, i, j));
      i = j;
    } else {
      std::size_t j = i;
      while (j < s.size() && std::isalnum(static_cast<unsigned char>(s[j]))) ++j;
      toks.push_back(jtok(JTok::Lit, i, std::max(j, i + 1)));
      i = std::max(j, i + 1);
    }
  }
  struct Frame {
    bool object;
    std::string path, key;
    std::size_t index = 0, open;
  };
  std::vector<Frame> stack;
  std::size_t root = 0;
  for (std::size_t k = 0; k < toks.size(); ++k) {
    JTok& t = toks[k];
    t.root = root;
    if (t.kind == JTok::Str && k + 1 < toks.size() && toks[k + 1].kind == JTok::Colon && !stack.empty() &&
        stack.back().object) {
      t.key = true;
      stack.back().key = s.substr(t.b + 1, t.e - t.b - 2);
      t.path = stack.back().path.empty() ? stack.back().key : stack.back().path + "." + stack.back().key;
      continue;
    }
    if (t.kind == JTok::Colon) continue;
    if (t.kind == JTok::Comma) {
      if (!stack.empty() && !stack.back().object) ++stack.back().index;
      continue;
    }
    if (t.kind == JTok::Close) {
      if (!stack.empty()) {
        toks[stack.back().open].e = t.e;
        stack.pop_back();
        if (stack.empty()) ++root;
      }
      continue;
    }
    std::string path;
    if (!stack.empty()) {
      const Frame& f = stack.back();
      path = f.object ? (f.path.empty() ? f.key : f.path + "." + f.key) : f.path + "[" + std::to_string(f.index) + "]";
    }
    t.path = path;
    if (t.kind == JTok::Open)
      stack.push_back({s[t.b] == '{', path, "", 0, k});
    else if (stack.empty())
      ++root;
  }
  return toks;
}

// Which keys a file of this kind cannot do without (removing one must be refused).
using Required = std::function<bool(std::size_t root, const std::string& path)>;

struct JsonKind {
  std::string name;
  bool lines;  // JSON Lines (a trace)
  Required required;
};

const std::vector<std::string> kWrongForNumber = {"\"x\"", "true", "null", "{}", "[]", "\"\"", "[1]"};
const std::vector<std::string> kWrongForString = {"0", "1.5", "true", "null", "[]", "{}", "-7"};
const std::vector<std::string> kWrongForLiteral = {"\"true\"", "1", "[]", "{}"};
const std::vector<std::string> kWrongForArray = {"1", "\"a\"", "{}", "null", "true"};
const std::vector<std::string> kWrongForObject = {"[]", "1", "\"o\"", "null", "false"};
const std::vector<std::string> kNanLike = {"NaN", "nan", "Infinity", "-Infinity", "inf", "0x10",  "+1",
                                           ".5",  "1.",  "01",       "1e",        "--1", "1_000", "Ox1"};
const std::vector<std::string> kHuge = {"1e400",
                                        "-1e400",
                                        kFiftyDigits,
                                        "-" + kFiftyDigits,
                                        "1e200",
                                        "1e308",
                                        "1.7976931348623157e308",
                                        "4.9e-324",
                                        "18446744073709551616",
                                        "9223372036854775808",
                                        "2147483648",
                                        "4294967296",
                                        "-0",
                                        "-0.0"};

std::string nested(std::size_t depth) { return std::string(depth, '[') + "1" + std::string(depth, ']'); }

Mutant json_mutant(Rng& rng, const std::string& op, const std::string& text, const std::vector<JTok>& toks,
                   const JsonKind& kind) {
  auto of_kind = [&](auto pred) {
    std::vector<std::size_t> v;
    for (std::size_t k = 0; k < toks.size(); ++k)
      if (pred(toks[k])) v.push_back(k);
    return v;
  };
  auto at = [&](const JTok& t) {
    return " (line " + std::to_string(t.root + 1) + " " + (t.path.empty() ? "$" : t.path) + ")";
  };
  auto where = [&](const JTok& t) {
    return kind.lines ? at(t) : " (" + (t.path.empty() ? std::string("$") : t.path) + ")";
  };
  const auto values = of_kind([](const JTok& t) {
    return !t.key && t.kind != JTok::Close && t.kind != JTok::Colon && t.kind != JTok::Comma && !t.path.empty();
  });
  const auto numbers = of_kind([](const JTok& t) { return t.kind == JTok::Num; });
  const auto strings = of_kind([](const JTok& t) { return t.kind == JTok::Str; });
  const auto keys = of_kind([](const JTok& t) { return t.key; });
  const std::vector<Line> lines = lines_of(text);

  if (op == "byte_flip") {
    Mutant m = byte_flip(rng, text);
    // Every shipped file is ASCII: a byte of 0x80 or more alone is never UTF-8, so never JSON.
    for (std::size_t i = 0; i < m.text.size(); ++i)
      if (static_cast<unsigned char>(m.text[i]) >= 0x80) m.bad = true;
    return m;
  }
  if (op == "truncate") {
    if (!kind.lines) {
      Mutant m = truncation(rng, text, text.rfind('}'));
      m.bad = true;  // the top-level object is never closed
      return m;
    }
    Mutant m = truncation(rng, text, text.size());
    // Cut inside a line: the last record is not JSON. Cut between lines: a shorter trace.
    const std::size_t cut = m.text.size();
    m.bad = cut == 0 || text[cut - 1] != '\n';
    return m;
  }
  if (op == "delete_line") {
    const std::size_t i = below(rng, lines.size());
    Mutant m = delete_line(text, lines, i);
    m.bad = kind.lines && i == 0;  // a trace without its header
    return m;
  }
  if (op == "duplicate_line") {
    Mutant m = duplicate_line(text, lines, below(rng, lines.size()));
    m.bad = kind.lines;  // a second header, or a record whose step does not increase
    return m;
  }
  if (op == "huge_coordinate") {
    // A position whose square (a distance) overflows a double: refused, or used without printing
    // inf or nan (checked for every run that succeeds).
    auto positions = of_kind([](const JTok& t) {
      if (t.kind != JTok::Num) return false;
      for (const char* k : {"at[", "start[", "robots[", "waypoint[", "x_m", "y_m"})
        if (t.path.find(k) != std::string::npos) return true;
      return false;
    });
    const JTok& t = toks[pick(rng, positions.empty() ? numbers : positions)];
    return replace(op, text, t.b, t.e,
                   pick(rng, std::vector<std::string>{"1e155", "-1e200", "1e300", "-1.7976931348623157e308"}),
                   where(t));
  }
  if (op == "wrong_type") {
    const JTok& t = toks[pick(rng, values)];
    const auto& choices = t.kind == JTok::Num   ? kWrongForNumber
                          : t.kind == JTok::Str ? kWrongForString
                          : t.kind == JTok::Lit ? kWrongForLiteral
                          : text[t.b] == '['    ? kWrongForArray
                                                : kWrongForObject;
    Mutant m = replace("wrong_type", text, t.b, t.e, pick(rng, choices), where(t));
    m.bad = true;
    return m;
  }
  if (op == "number_to_string") {
    const JTok& t = toks[pick(rng, numbers)];
    Mutant m = replace("number_to_string", text, t.b, t.e, "\"" + text.substr(t.b, t.e - t.b) + "\"", where(t));
    m.bad = true;
    return m;
  }
  if (op == "huge_number") {
    const JTok& t = toks[pick(rng, numbers)];
    const std::string with = pick(rng, kHuge);
    Mutant m = replace("huge_number", text, t.b, t.e, with, where(t));
    m.bad = with == "1e400" || with == "-1e400";  // no double holds it; the rest may fit some field
    return m;
  }
  if (op == "negative") {
    const JTok& t = toks[pick(rng, numbers)];
    const std::string v = text.substr(t.b, t.e - t.b);
    const std::string with = below(rng, 2) ? "-1" : (v[0] == '-' ? "-" + v : "-" + v + "7");
    return replace("negative", text, t.b, t.e, with, where(t));
  }
  if (op == "nan_token") {
    const JTok& t = toks[pick(rng, below(rng, 4) ? numbers : values)];
    Mutant m = replace("nan_token", text, t.b, t.e, pick(rng, kNanLike), where(t));
    m.bad = true;  // none of these is JSON
    return m;
  }
  if (op == "deep_nesting") {
    const JTok& t = toks[pick(rng, values)];
    const std::size_t depth = pick(rng, std::vector<std::size_t>{3, 64, 1000, 100000});
    Mutant m = replace("deep_nesting", text, t.b, t.e, nested(depth), where(t));
    m.what = line_col(text, t.b) + where(t) + ": '" + shown(text.substr(t.b, t.e - t.b), 60) + "' -> [[[...1...]]] " +
             std::to_string(depth) + " deep";
    m.bad = true;  // no field of any format holds a list of lists of lists
    return m;
  }
  if (op == "remove_key") {
    const std::size_t k = pick(rng, keys);
    const JTok& key = toks[k];
    const JTok& value = toks[k + 2];
    std::size_t b = key.b, e = value.e;
    if (k + 3 < toks.size() && toks[k + 3].kind == JTok::Comma) {
      e = toks[k + 3].e;
    } else if (k > 0 && toks[k - 1].kind == JTok::Comma) {
      b = toks[k - 1].b;
    }
    Mutant m;
    m.op = "remove_key";
    m.text = text.substr(0, b) + text.substr(e);
    m.what = line_col(text, key.b) + where(key) + ": member '" + shown(text.substr(key.b, value.e - key.b), 80) +
             "' removed";
    m.bad = kind.required(key.root, key.path);
    return m;
  }
  if (op == "duplicate_key") {
    const std::size_t k = pick(rng, keys);
    const JTok& key = toks[k];
    const JTok& value = toks[k + 2];
    // The same member again, before the first; half the time with a different value.
    std::string member = text.substr(key.b, value.e - key.b);
    if (below(rng, 2) && value.kind == JTok::Num) member = text.substr(key.b, value.b - key.b) + "0";
    Mutant m;
    m.op = "duplicate_key";
    m.text = text.substr(0, key.b) + member + ", " + text.substr(key.b);
    m.what = line_col(text, key.b) + where(key) + ": member '" + shown(member, 80) + "' inserted before its twin";
    m.bad = true;
    return m;
  }
  if (op == "unknown_key") {
    const auto objects = of_kind([&](const JTok& t) { return t.kind == JTok::Open && text[t.b] == '{'; });
    const JTok& t = toks[pick(rng, objects)];
    const bool empty = text.find_first_not_of(" \t\r\n", t.b + 1) == t.e - 1;
    const std::string member = std::string("\"zz_unknown\": 1") + (empty ? "" : ", ");
    Mutant m = replace("unknown_key", text, t.b + 1, t.b + 1, member, where(t));
    m.bad = true;  // every format lists its keys exactly
    return m;
  }
  if (op == "invalid_utf8") {
    // Into a name when there is one (the value of a "name" key), else into any string.
    auto names = of_kind([&](const JTok& t) {
      return t.kind == JTok::Str && !t.key && t.path.size() >= 4 && t.path.compare(t.path.size() - 4, 4, "name") == 0;
    });
    const JTok& t = toks[pick(rng, names.empty() || below(rng, 3) == 0 ? strings : names)];
    const std::size_t at_byte = t.b + 1 + below(rng, t.e - t.b - 1);
    const std::string bytes = pick(rng, kInvalidUtf8);
    Mutant m = replace("invalid_utf8", text, at_byte, at_byte, bytes, where(t));
    m.what += " in string " + shown(text.substr(t.b, t.e - t.b), 60);
    m.bad = true;  // JSON text is UTF-8
    return m;
  }
  if (op == "escaped_control") {
    // Valid JSON for a control character: the message quoting it must escape it, not emit it.
    auto values_str = of_kind([](const JTok& t) { return t.kind == JTok::Str && !t.key; });
    const JTok& t = toks[pick(rng, values_str.empty() ? strings : values_str)];
    return replace(op, text, t.b, t.e,
                   pick(rng, std::vector<std::string>{"\"\\u001b[2J\\u001b[31mred\"", "\"two\\nlines\"",
                                                      "\"nul\\u0000byte\"", "\"cr\\rover\"", "\"bell\\u0007\""}),
                   where(t));
  }
  if (op == "unterminated_string") {
    // A string that never ends, running to the end of the file: the message must not quote it all.
    const JTok& t = toks[pick(rng, strings)];
    Mutant m;
    m.op = op;
    m.text = text.substr(0, t.b) + "\"" + std::string(5000, 'x');
    m.what = line_col(text, t.b) + where(t) + ": '" + shown(text.substr(t.b, t.e - t.b), 60) +
             "' -> '\"xxx...' (5000 x, no closing quote, end of file)";
    m.bad = true;
    return m;
  }
  if (op == "whitespace") {
    // Valid and equivalent: extra white space between tokens (only blanks within a JSON Lines line).
    std::string t = text;
    std::vector<std::size_t> spots;
    for (int n = 0; n < 6; ++n) spots.push_back(toks[below(rng, toks.size())].b);
    std::sort(spots.rbegin(), spots.rend());
    const std::vector<std::string> ws = kind.lines ? std::vector<std::string>{" ", "\t", "  \t "}
                                                   : std::vector<std::string>{" ", "\t", "\n", "\r\n", " \n\t "};
    for (std::size_t p : spots) t.insert(p, pick(rng, ws));
    Mutant m;
    m.op = "whitespace";
    m.text = t;
    m.what = "white space added before 6 tokens";
    m.same = true;
    return m;
  }
  ADD_FAILURE() << "unknown mutation " << op;
  return {};
}

const std::vector<std::string> kJsonOps = {
    "byte_flip",     "truncate",        "delete_line",  "duplicate_line",  "wrong_type",          "number_to_string",
    "huge_number",   "huge_coordinate", "negative",     "nan_token",       "deep_nesting",        "remove_key",
    "duplicate_key", "unknown_key",     "invalid_utf8", "escaped_control", "unterminated_string", "whitespace"};

// UMDES .fsm text: each whitespace-separated field with what it is, read from the (valid) original.
struct FTok {
  enum Kind { Count, StateName, Marked, NTrans, Event, Target, Attr, EventsWord, DeclEvent } kind;
  std::size_t b, e;
};

std::vector<FTok> fsm_tokens(const std::string& text, std::size_t& last_block_line_begin) {
  std::vector<FTok> toks;
  bool seen_count = false, in_events = false;
  long pending = -1;  // transitions still to come in this block; -1: expecting a state header
  for (const Line& l : lines_of(text)) {
    std::vector<std::pair<std::size_t, std::size_t>> f;
    for (std::size_t i = l.begin; i < l.end;) {
      while (i < l.end && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
      std::size_t j = i;
      while (j < l.end && !std::isspace(static_cast<unsigned char>(text[j]))) ++j;
      if (j > i) f.emplace_back(i, j);
      i = j;
    }
    if (f.empty()) continue;
    if (!seen_count) {
      toks.push_back({FTok::Count, f[0].first, f[0].second});
      seen_count = true;
    } else if (in_events) {
      toks.push_back({FTok::DeclEvent, f[0].first, f[0].second});
      for (std::size_t k = 1; k < f.size(); ++k) toks.push_back({FTok::Attr, f[k].first, f[k].second});
    } else if (pending <= 0 && text.compare(f[0].first, 6, "EVENTS") == 0 && f.size() == 1) {
      toks.push_back({FTok::EventsWord, f[0].first, f[0].second});
      in_events = true;
    } else if (pending <= 0) {
      toks.push_back({FTok::StateName, f[0].first, f[0].second});
      toks.push_back({FTok::Marked, f[1].first, f[1].second});
      toks.push_back({FTok::NTrans, f[2].first, f[2].second});
      pending = std::stol(text.substr(f[2].first, f[2].second - f[2].first));
      last_block_line_begin = l.begin;
    } else {
      toks.push_back({FTok::Event, f[0].first, f[0].second});
      toks.push_back({FTok::Target, f[1].first, f[1].second});
      for (std::size_t k = 2; k < f.size(); ++k) toks.push_back({FTok::Attr, f[k].first, f[k].second});
      --pending;
      last_block_line_begin = l.begin;
    }
  }
  return toks;
}

const std::vector<std::string> kFsmOps = {"byte_flip",
                                          "truncate",
                                          "delete_line",
                                          "duplicate_line",
                                          "bad_number",
                                          "invalid_utf8_name",
                                          "rename_invalid_utf8",
                                          "bad_attribute",
                                          "bad_target",
                                          "crlf",
                                          "spaces_and_blank_lines"};
const std::vector<std::string> kBadNumbers = {
    "1e400",       "-1",         kFiftyDigits,           "NaN", "inf", "x", "0x10", "2.5",
    "99999999999", "4294967297", "18446744073709551617", "1e9", "-0"};

Mutant fsm_mutant(Rng& rng, const std::string& op, const std::string& text) {
  std::size_t last_block_line = 0;
  const std::vector<FTok> toks = fsm_tokens(text, last_block_line);
  auto of = [&](std::initializer_list<FTok::Kind> kinds) {
    std::vector<FTok> v;
    for (const FTok& t : toks)
      if (std::find(kinds.begin(), kinds.end(), t.kind) != kinds.end()) v.push_back(t);
    return v;
  };
  const std::vector<Line> lines = lines_of(text);
  const std::size_t events_at = text.find("\nEVENTS");
  if (op == "byte_flip") return byte_flip(rng, text);
  if (op == "truncate") {
    Mutant m = truncation(rng, text, text.size());
    m.bad = m.text.size() <= last_block_line;  // at least one declared transition or state is gone
    return m;
  }
  if (op == "delete_line") {
    std::vector<std::size_t> nonblank;
    for (std::size_t i = 0; i < lines.size(); ++i)
      if (!blank(text, lines[i])) nonblank.push_back(i);
    const std::size_t i = pick(rng, nonblank);
    Mutant m = delete_line(text, lines, i);
    m.bad = events_at == std::string::npos || lines[i].begin <= events_at;  // a count no longer matches
    return m;
  }
  if (op == "duplicate_line") return duplicate_line(text, lines, below(rng, lines.size()));
  if (op == "bad_number") {
    const FTok t = pick(rng, of({FTok::Count, FTok::Marked, FTok::NTrans}));
    Mutant m = replace("bad_number", text, t.b, t.e, pick(rng, kBadNumbers), "");
    m.bad = true;
    return m;
  }
  if (op == "invalid_utf8_name") {
    const FTok t = pick(rng, of({FTok::StateName, FTok::Event, FTok::Target, FTok::DeclEvent}));
    const std::size_t at_byte = t.b + below(rng, t.e - t.b + 1);
    return replace("invalid_utf8_name", text, at_byte, at_byte, pick(rng, kInvalidUtf8),
                   " in name '" + text.substr(t.b, t.e - t.b) + "'");
  }
  if (op == "rename_invalid_utf8") {
    // A state (the initial one half the time) or an event renamed everywhere with bytes that are
    // not UTF-8: still a well-formed automaton, so 0, 1 or 2, but its name reaches the output.
    const bool state = below(rng, 3) != 0;
    const auto names =
        of(state ? std::initializer_list<FTok::Kind>{FTok::StateName} : std::initializer_list<FTok::Kind>{FTok::Event});
    const FTok t = state && below(rng, 2) ? names.front() : pick(rng, names);
    const std::string old_name = text.substr(t.b, t.e - t.b);
    const std::string bytes = pick(rng, kInvalidUtf8);
    const std::string new_name = old_name.substr(0, 1) + bytes + old_name.substr(1);
    Mutant m;
    m.op = op;
    std::size_t from = 0;
    for (const FTok& u : toks) {
      if (text.compare(u.b, u.e - u.b, old_name) != 0 || u.e - u.b != old_name.size()) continue;
      m.text += text.substr(from, u.b - from) + new_name;
      from = u.e;
    }
    m.text += text.substr(from);
    m.what =
        std::string(state ? "state" : "event") + " '" + old_name + "' renamed '" + shown(new_name) + "' everywhere";
    return m;
  }
  if (op == "bad_attribute") {
    const FTok t = pick(rng, of({FTok::Attr}));
    Mutant m = replace("bad_attribute", text, t.b, t.e,
                       pick(rng, std::vector<std::string>{"x", "C", "UC", "ucc", "c/uc", "\xff", "-"}), "");
    m.bad = true;
    return m;
  }
  if (op == "bad_target") {
    const FTok t = pick(rng, of({FTok::Target}));
    Mutant m =
        replace("bad_target", text, t.b, t.e, pick(rng, std::vector<std::string>{"42", "-1", kFiftyDigits, "s1x"}), "");
    m.bad = true;  // no state has that name
    return m;
  }
  if (op == "crlf") {
    Mutant m;
    m.op = "crlf";
    for (char c : text) m.text += c == '\n' ? std::string("\r\n") : std::string(1, c);
    m.what = "every line ending CRLF";
    m.same = true;
    return m;
  }
  if (op == "spaces_and_blank_lines") {
    Mutant m;
    m.op = "spaces_and_blank_lines";
    for (char c : text) {
      if (c == '\t')
        m.text += pick(rng, std::vector<std::string>{" ", "  ", " \t", "\t\t"});
      else if (c == '\n' && below(rng, 8) == 0)
        m.text += "\n\n";
      else
        m.text += c;
    }
    m.what = "tabs as runs of blanks, blank lines added";
    m.same = true;
    return m;
  }
  ADD_FAILURE() << "unknown mutation " << op;
  return {};
}

// ---------------------------------------------------------------------------------------------
// The harness: run each command on each mutant, check the contract, gather what broke.

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

std::uint64_t seed_for(std::uint64_t fixed) {
  const char* s = std::getenv("SWARMCHECK_MUTATION_SEED");
  return s ? std::strtoull(s, nullptr, 10) ^ fixed : fixed;
}

std::size_t count_for(std::size_t fixed) {
  const char* s = std::getenv("SWARMCHECK_MUTATIONS");
  return s ? std::strtoul(s, nullptr, 10) : fixed;
}

std::string joined(const std::vector<std::string>& args) {
  std::string r = "swarmcheck";
  for (const auto& a : args) r += " " + a;
  return r;
}

// What went wrong with one run: a class (failures are grouped by it) and the particulars.
struct Problem {
  std::string kind, detail;
};

bool names_inf_or_nan(const std::string& out) {
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
void check_message(const Outcome& o, const fs::path& input, std::vector<Problem>& p) {
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
std::vector<Problem> problems(const Mutant& m, const Outcome& o, int original_status, const fs::path& input,
                              const std::string& input_before, const fs::path& output, bool writes, const fs::path& dir,
                              const std::set<std::string>& expected_files) {
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

std::vector<Mutant> json_mutants(const std::string& text, const JsonKind& kind, std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  const auto toks = json_tokens(text);
  std::vector<Mutant> v;
  for (std::size_t i = 0; i < n; ++i) v.push_back(json_mutant(rng, kJsonOps[i % kJsonOps.size()], text, toks, kind));
  return v;
}

std::vector<Mutant> fsm_mutants(const std::string& text, std::size_t n, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<Mutant> v;
  for (std::size_t i = 0; i < n; ++i) v.push_back(fsm_mutant(rng, kFsmOps[i % kFsmOps.size()], text));
  return v;
}

std::string test_name() { return ::testing::UnitTest::GetInstance()->current_test_info()->name(); }

}  // namespace

TEST(MutationCli, AMutatedScenarioGivesStatus0Or1Or2WithOneMessageNamingItAndLeavesTheTraceOutputWhole) {
  MutationHarness h(test_name());
  const JsonKind scenario{"scenario", false,
                          [](std::size_t, const std::string& path) { return path == "map_size" || path == "robots"; }};
  const std::vector<Command> run{{"run --steps 50 --trace OUT",
                                  [](const std::string& in, const std::string& out) {
                                    return std::vector<std::string>{"run", in, "--steps", "50", "--trace", out};
                                  },
                                  true}};
  std::uint64_t salt = 0;
  for (const auto& [file, n] : std::vector<std::pair<std::string, std::size_t>>{
           {"scenarios/default.json", count_for(120)}, {"scenarios/examples/warehouse.json", count_for(90)}}) {
    const std::string text = read_bytes(kSource + "/" + file);
    h.check(fs::path(file).filename().string(), text, json_mutants(text, scenario, n, seed_for(0x5eed0001 + salt++)),
            run);
  }
  h.report();
}

TEST(MutationCli, AMutatedMissionGivesStatus0Or1Or2WithOneMessageNamingItAndLeavesTheTraceOutputWhole) {
  MutationHarness h(test_name());
  h.fixture(kSource + "/scenarios/thesis/control2.fsm");
  // Every key of a mission is needed except the free text "about" and the meanings of events the
  // FSM does not have (checked, then ignored).
  std::set<std::string> fsm_events;
  {
    std::istringstream in(read_bytes(kSource + "/scenarios/thesis/control2.fsm"));
    for (std::string line; std::getline(in, line);) {
      std::istringstream f(line);
      std::vector<std::string> fields{std::istream_iterator<std::string>(f), {}};
      if (fields.size() == 4) fsm_events.insert(fields[0]);
    }
  }
  ASSERT_TRUE(fsm_events.count("a5e"));
  const JsonKind mission{"mission", false, [fsm_events](std::size_t, const std::string& path) {
                           if (path == "about") return false;
                           if (path.rfind("events.", 0) == 0 && path.find('.', 7) == std::string::npos)
                             return fsm_events.count(path.substr(7)) > 0;
                           return true;
                         }};
  const std::vector<Command> commands{{"mission plan",
                                       [](const std::string& in, const std::string&) {
                                         return std::vector<std::string>{"mission", "plan", in};
                                       }},
                                      {"mission run --trace OUT",
                                       [](const std::string& in, const std::string& out) {
                                         return std::vector<std::string>{"mission",   "run",     in,    "--body",
                                                                         "kinematic", "--speed", "100", "--max-time",
                                                                         "100",       "--trace", out};
                                       },
                                       true}};
  const std::string text = read_bytes(kSource + "/scenarios/thesis/thesis-mission.json");
  h.check("thesis-mission.json", text, json_mutants(text, mission, count_for(150), seed_for(0x5eed0002)), commands);
  h.report();
}

TEST(MutationCli, AMutatedFsmFileGivesStatus0Or1Or2WithOneMessageNamingItAndLeavesTheExportOutputWhole) {
  MutationHarness h(test_name());
  const std::vector<Command> commands{{"fsm check",
                                       [](const std::string& in, const std::string&) {
                                         return std::vector<std::string>{"fsm", "check", in};
                                       }},
                                      {"fsm check --json",
                                       [](const std::string& in, const std::string&) {
                                         return std::vector<std::string>{"fsm", "check", in, "--json"};
                                       }},
                                      {"fsm export --to json -o OUT",
                                       [](const std::string& in, const std::string& out) {
                                         return std::vector<std::string>{"fsm",  "export", in, "--to",
                                                                         "json", "-o",     out};
                                       },
                                       true}};
  std::uint64_t salt = 0;
  for (const std::string file : {"control2.fsm", "supervisor.fsm", "supervisor_any_robot.fsm"}) {
    const std::string text = read_bytes(kSource + "/scenarios/thesis/" + file);
    h.check(file, text, fsm_mutants(text, count_for(50), seed_for(0x5eed0003 + salt++)), commands);
  }
  h.report();
}

TEST(MutationCli, AMutatedTraceGivesStatus0Or1Or2WithOneMessageNamingIt) {
  MutationHarness h(test_name());
  const fs::path made = h.dir() / "made.jsonl";
  const Outcome o = run_swarmcheck({"run", "--steps", "30", "--trace", made.string()}, std::chrono::seconds(20));   // 30 steps: not completed (status 1)
  ASSERT_EQ(o.status, 1) << o.err;
  const std::string text = read_bytes(made);
  fs::remove(made);
  // A record must have every field; so must the header, except inside its scenario, where a
  // missing key takes the same default as in a scenario file.
  const JsonKind trace{"trace", true, [](std::size_t root, const std::string& path) {
                         if (root == 0 && path.rfind("scenario.", 0) == 0)
                           return path == "scenario.map_size" || path == "scenario.robots";
                         return true;
                       }};
  const std::vector<Command> replay{{"replay", [](const std::string& in, const std::string&) {
                                       return std::vector<std::string>{"replay", in};
                                     }}};
  h.check("t.jsonl", text, json_mutants(text, trace, count_for(120), seed_for(0x5eed0004)), replay);
  h.report();
}

// Not mutations but the same contract: files that are not regular text files.
TEST(MutationCli, AnEmptyMissingDirectoryDeviceOrFifoInputIsStatus2WithinSecondsNotAHangOrACrash) {
  MutationHarness h(test_name());
  const fs::path empty = h.dir() / "empty.json";
  write_bytes(empty, "");
  const fs::path folder = h.dir() / "folder.json";
  fs::create_directories(folder);
  const fs::path fifo = h.dir() / "fifo.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::vector<std::string> inputs{
      empty.string(), (h.dir() / "missing.json").string(), folder.string(), "/dev/null", "/dev/zero", fifo.string()};
  std::vector<std::string> broken;
  for (const std::vector<std::string>& verb : std::vector<std::vector<std::string>>{
           {"run", "--steps", "5"}, {"replay"}, {"mission", "plan"}, {"fsm", "check"}, {"fsm", "check", "--json"}}) {
    for (const std::string& in : inputs) {
      std::vector<std::string> args = verb;
      args.insert(args.begin() + (verb[0] == "run" ? 1 : static_cast<long>(verb.size())), in);
      // Each is refused at once: a short limit on time and memory keeps a failure cheap.
      const Outcome o = run_swarmcheck(args, std::chrono::seconds(2), 512);
      const std::string name = fs::path(in).filename().string();
      const std::string first = o.err.substr(0, o.err.find('\n'));
      std::string what;
      if (o.timed_out)
        what = "no answer within 2 s";
      else if (o.signal)
        what = "signal " + std::to_string(o.signal);
      else if (o.status != 2)
        what = "status " + std::to_string(o.status);
      else if (first.find(name) == std::string::npos)
        what = "the first line of stderr does not name " + name;
      else if (std::count(o.err.begin(), o.err.end(), '\n') + std::count(o.out.begin(), o.out.end(), '\n') > 3)
        what = "more than 3 lines";
      if (!what.empty()) broken.push_back(joined(args) + ": " + what + "; stderr: " + shown(o.err, 200));
    }
  }
  EXPECT_TRUE(fs::exists(fifo) && fs::is_empty(folder));
  std::string all;
  for (const auto& b : broken) all += "  " + b + "\n";
  EXPECT_TRUE(broken.empty()) << broken.size() << " inputs broke the contract:\n" << all;
}
