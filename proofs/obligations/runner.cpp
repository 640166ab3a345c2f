#include "proofs/obligations/runner.hpp"

#include <fmt/format.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <system_error>

#include "spec/util/json_text.hpp"

namespace swarmcheck::proofs {
namespace {

using Json = nlohmann::json;
using Clock = std::chrono::steady_clock;

Json to_json(const ObligationReport& r) {
  Json queries = Json::array();
  for (const QueryRecord& q : r.queries)
    queries.push_back({{"label", q.label}, {"smt2", q.smt2}, {"answer", q.answer}, {"seconds", q.seconds}});
  Json j = {{"result", to_string(r.result)}, {"detail", r.detail}, {"queries", queries},
            {"reads", r.reads}, {"step_calls", r.step_calls}};
  if (r.trace) j["trace"] = {{"file_name", r.trace->file_name}, {"text", r.trace->text}};
  return j;
}

void from_json(const Json& j, ObligationReport& r) {
  r.result = verdict_from_string(j.at("result").get<std::string>());
  r.detail = j.at("detail").get<std::string>();
  for (const Json& q : j.at("queries"))
    r.queries.push_back(QueryRecord{q.at("label").get<std::string>(), q.at("smt2").get<std::string>(),
                                    q.at("answer").get<std::string>(), q.at("seconds").get<double>()});
  r.reads = j.at("reads").get<std::vector<std::string>>();
  r.step_calls = j.at("step_calls").get<std::vector<std::string>>();
  r.unread = unread_step_calls(r.step_calls, r.reads);
  if (j.contains("trace"))
    r.trace = TraceFile{j["trace"].at("file_name").get<std::string>(),
                        j["trace"].at("text").get<std::string>()};
}

ObligationReport skeleton(const Obligation& o) {
  ObligationReport r;
  r.name = o.name;
  r.property = o.property;
  r.expected = o.expected;
  r.assumptions = o.assumptions;
  return r;
}

// Runs the obligation and fills in result, detail, queries and trace (not the time).
void run_body(const Obligation& o, unsigned query_timeout_ms, ObligationReport& r) {
  Session session(query_timeout_ms);
  try {
    Outcome out = o.run(session);
    r.result = out.verdict;
    r.detail = std::move(out.detail);
    r.trace = std::move(out.trace);
  } catch (const z3::exception& e) {
    r.result = Verdict::unknown;
    r.detail = std::string("z3 error: ") + e.msg();
  } catch (const std::exception& e) {
    r.result = Verdict::unknown;
    r.detail = std::string("error: ") + e.what();
  }
  r.queries = session.queries();
  r.reads.assign(session.reads().begin(), session.reads().end());
  try {
    if (o.step) r.step_calls = sym::called_functions(o.step());
  } catch (const std::exception& e) {
    r.result = Verdict::unknown;
    r.detail += std::string("; the step's symbolic interpretation failed: ") + e.what();
  }
  r.unread = unread_step_calls(r.step_calls, r.reads);
}

void write_all(int fd, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    done += static_cast<std::size_t>(n);
  }
}

}  // namespace

std::vector<std::string> unread_step_calls(const std::vector<std::string>& step_calls,
                                           const std::vector<std::string>& reads) {
  std::vector<std::string> out;
  for (const std::string& f : step_calls)
    if (std::find(reads.begin(), reads.end(), f) == reads.end()) out.push_back(f);
  return out;
}

const Obligation* find_obligation(const std::string& name) {
  for (const Obligation& o : all_obligations())
    if (o.name == name) return &o;
  return nullptr;
}

ObligationReport run_in_process(const Obligation& o, unsigned query_timeout_ms) {
  ObligationReport r = skeleton(o);
  const auto start = Clock::now();
  run_body(o, query_timeout_ms, r);
  r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return r;
}

ObligationReport run_isolated(const Obligation& o, double timeout_s, unsigned query_timeout_ms) {
  ObligationReport r = skeleton(o);
  int fds[2];
  if (::pipe(fds) != 0) throw std::system_error(errno, std::generic_category(), "pipe");
  std::fflush(nullptr);   // the child must not flush our buffered output a second time
  const auto start = Clock::now();
  const pid_t pid = ::fork();
  if (pid < 0) throw std::system_error(errno, std::generic_category(), "fork");
  if (pid == 0) {
    ::close(fds[0]);
    ObligationReport child = skeleton(o);
    run_body(o, query_timeout_ms, child);
    write_all(fds[1], to_json(child).dump());
    ::close(fds[1]);
    ::_exit(0);
  }
  ::close(fds[1]);
  const auto deadline = start + std::chrono::duration<double>(timeout_s);
  std::string text;
  bool timed_out = false;
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    if (left.count() <= 0) {
      timed_out = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(left.count()));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;   // re-evaluates the deadline
    char buf[65536];
    const ssize_t n = ::read(fds[0], buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;   // EOF: the child is done
    text.append(buf, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  if (timed_out) ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (timed_out) {
    r.result = Verdict::unknown;
    r.detail = fmt::format("watchdog: no answer within {} s, the prover was killed", timeout_s);
    return r;
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || text.empty()) {
    r.result = Verdict::unknown;
    r.detail = WIFSIGNALED(status)
                   ? fmt::format("the prover died with signal {}", WTERMSIG(status))
                   : std::string("the prover exited without a report");
    return r;
  }
  try {
    from_json(Json(json_io::parse_json_text(text, "the prover's report")), r);
  } catch (const std::exception& e) {
    r.result = Verdict::unknown;
    r.detail = std::string("unreadable report from the prover: ") + e.what();
  }
  return r;
}

}  // namespace swarmcheck::proofs
