#include "views/fsm_svg.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

#include "spec/util/demand.hpp"
#include "impl/io/interrupt.hpp"
#include "spec/util/input_error.hpp"

extern char** environ;   // POSIX: the environment dot inherits

namespace swarmcheck::views {
namespace {

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string find_dot() {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/bin");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::string candidate = (dir.empty() ? "." : dir) + "/dot";
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return {};
}

// Removes its file when it goes out of scope.
struct TempFile {
  std::string path;
  TempFile() {
    std::string tmpl = (std::filesystem::temp_directory_path() / "swarmcheck-dot-XXXXXX").string();
    const int fd = ::mkstemp(tmpl.data());
    if (fd < 0) throw InputError(tmpl, "cannot create a temporary file for dot");
    ::close(fd);
    path = tmpl;
    slot = impl::io::register_temp_file(path.c_str());   // removed on SIGINT/SIGTERM too
  }
  ~TempFile() {
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
    impl::io::release_temp_file(slot);
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  int slot = -1;
};

}  // namespace

bool dot_available() { return !find_dot().empty(); }

std::string styled_dot(const swarmcheck::supervisor::Automaton& a) {
  std::string out =
      "digraph fsm {\n  rankdir=LR;\n  bgcolor=\"transparent\";\n"
      "  node [shape=circle, fontname=\"DejaVu Sans\", fontsize=11, style=filled, fillcolor=\"#ffffff\", color=\"#334155\"];\n"
      "  edge [fontname=\"DejaVu Sans\", fontsize=10, arrowsize=0.7];\n";
  if (!a.states.empty())
    out += "  __start [shape=point, width=0.08, label=\"\"];\n  __start -> " + quoted(a.states.front()) +
           " [color=\"#334155\"];\n";
  for (const auto& q : a.states) {
    out += "  " + quoted(q) + " [id=" + quoted("state:" + q);
    if (a.marked.count(q)) out += ", shape=doublecircle, fillcolor=\"#e0f2fe\"";
    if (!a.states.empty() && q == a.states.front()) out += ", penwidth=2";
    out += "];\n";
  }
  for (const auto& q : a.states) {
    const auto row = a.delta.find(q);
    if (row == a.delta.end()) continue;
    for (const auto& [e, target] : row->second) {
      const bool c = a.events.at(e).controllable;
      out += "  " + quoted(q) + " -> " + quoted(target) + " [label=" + quoted(e) + ", id=" +
             quoted("edge:" + q + "|" + e) + ", class=" + quoted(c ? "c" : "uc");
      out += c ? ", color=\"#1d4ed8\", fontcolor=\"#1d4ed8\", dir=both, arrowtail=tee"
               : ", color=\"#b91c1c\", fontcolor=\"#b91c1c\", style=dashed";
      out += "];\n";
    }
  }
  return out + "}\n";
}

std::optional<std::string> fsm_svg_within(const swarmcheck::supervisor::Automaton& a, std::chrono::milliseconds limit,
                                          const std::atomic<bool>* cancel) {
  const std::string dot = find_dot();
  if (dot.empty())
    throw InputError("graphviz", "the `dot` program is not installed (Debian: apt-get install graphviz); "
                                 "it lays out automata for `view` and `fsm export --to svg`");
  TempFile in, out, messages;
  {
    std::ofstream f(in.path);
    f << styled_dot(a);
  }
  // dot's own output and errors go to a file; the program itself is waited for with a deadline
  // (a dense automaton under the transition cap can take dot hours; a server's worker must not).
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, STDOUT_FILENO, messages.path.c_str(), O_WRONLY | O_TRUNC, 0600);
  posix_spawn_file_actions_adddup2(&files, STDOUT_FILENO, STDERR_FILENO);
  std::vector<std::string> args = {dot, "-Tsvg", "-o", out.path, in.path};
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, dot.c_str(), &files, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&files);
  if (spawned != 0) throw InputError("graphviz", std::string("cannot start dot: ") + std::strerror(spawned));
  // Killed with the process if a signal ends it (it would lay out for hours, into a temporary file).
  struct Child {
    int slot;
    ~Child() { impl::io::release_child(slot); }
  } child{impl::io::register_child(pid)};
  const auto deadline = std::chrono::steady_clock::now() + limit;
  int status = 0;
  for (auto pause = std::chrono::microseconds(200);; pause = std::min(pause * 2, std::chrono::microseconds(20000))) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) throw InputError("graphviz", std::string("lost dot: ") + std::strerror(errno));
    if (std::chrono::steady_clock::now() >= deadline || (cancel && cancel->load())) {
      ::kill(pid, SIGKILL);
      while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      return std::nullopt;
    }
    std::this_thread::sleep_for(pause);
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::ifstream m(messages.path);
    std::stringstream text;
    text << m.rdbuf();
    throw InputError("graphviz", "dot failed: " + text.str());
  }
  std::ifstream svg(out.path);
  std::stringstream text;
  text << svg.rdbuf();
  std::string s = text.str();
  const std::size_t at = s.find("<svg");   // drop the XML prolog and DOCTYPE
  SWARM_DEMAND(at != std::string::npos);
  return s.substr(at);
}

std::string fsm_svg(const swarmcheck::supervisor::Automaton& a) {
  if (auto svg = fsm_svg_within(a, kLayoutTimeMax)) return *svg;
  throw InputError("graphviz", fmt::format("dot did not lay out the automaton ({} states, {} transitions) within {} s; "
                                           "`view` lists its states instead", a.states.size(),
                                           swarmcheck::supervisor::transition_count(a),
                                           std::chrono::duration_cast<std::chrono::seconds>(kLayoutTimeMax).count()));
}

}  // namespace swarmcheck::views
