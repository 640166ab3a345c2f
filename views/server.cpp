#include "views/server.hpp"

#include "spec/util/input_error.hpp"

#ifdef SWARMCHECK_HAVE_HTTPLIB

#include <httplib.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <fmt/format.h>
#include <mutex>
#include <regex>
#include <thread>

#include "impl/io/interrupt.hpp"
#include "spec/exploration/scenario.hpp"
#include "spec/util/json_text.hpp"
#include "views/edit.hpp"
#include "views/http_connection.hpp"
#include "views/request_policy.hpp"
#include "views/schema.hpp"
#include "views/server_state.hpp"
#include "views/view.hpp"

namespace swarmcheck::views {

void bad_request(httplib::Response& res, int status, const std::string& message) {
  res.status = status;
  res.set_content("swarmcheck: error: " + message + "\n", "text/plain; charset=utf-8");
}

namespace serving {   // named: views/ is a unity build

using json_io::Json;

// A file posted to /api/view: {"name": "run.jsonl", "text": "..."}; the name is only shown (in
// messages and the page's title), never opened.
std::pair<std::string, std::string> posted_file(const std::string& body) {
  const Json j = json_io::parse_json_text(body, "request body");
  if (!j.is_object()) throw InputError("request body: (top level)", "expected {\"name\": FILE NAME, \"text\": THE FILE'S TEXT}");
  try {
    json_io::refuse_unknown_keys(j, "", {"name", "text"});
  } catch (const InputError& e) {
    throw InputError("request body", e.what());
  }
  const std::string name = json_io::string_member(j, "name");
  if (!j.contains("name") || !j["name"].is_string() || name.empty() || name.size() > 255 ||
      std::any_of(name.begin(), name.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == '/' || c == 0x7f; }))
    throw InputError("request body: name", "expected the file's name (1 to 255 characters, no '/' or control characters)");
  if (!j.contains("text") || !j["text"].is_string()) throw InputError("request body: text", "expected the file's text as a string");
  return {name, j["text"].get<std::string>()};
}

void page_routes(httplib::Server& svr, ServeState& state) {
  const ServeOptions& o = state.o;
  svr.Get("/", [](const httplib::Request&, httplib::Response& res) {
    res.set_content(assemble_page(live_page()), "text/html; charset=utf-8");
  });
  svr.Get("/editor", [](const httplib::Request&, httplib::Response& res) {
    res.set_content(assemble_page(scenario_editor_page("")), "text/html; charset=utf-8");
  });
  svr.Get("/api/schema", [](const httplib::Request&, httplib::Response& res) {
    res.set_content(scenario_schema().dump(2), "application/json");
  });
  // A trace or an .fsm file picked in the page: the view `swarmcheck view` would write. A mission
  // trace needs its mission file, which the server does not read: that one is `view`'s. At most
  // views_max at once: an automaton's layout runs dot, for up to 20 s.
  svr.Post("/api/view", [&state, &o](const httplib::Request& req, httplib::Response& res) {
    if (state.views_building.fetch_add(1) >= o.views_max) {
      --state.views_building;
      return bad_request(res, 429, fmt::format("{} views are being built (the limit: an automaton's layout may take dot 20 s); retry", o.views_max));
    }
    struct Release {
      std::atomic<int>& n;
      ~Release() { --n; }
    } release{state.views_building};
    try {
      const auto [where, text] = posted_file(req.body);
      Page page;
      switch (detect_view_kind(text, where)) {
        case ViewKind::exploration:
        case ViewKind::counterexample: page = exploration_page(text, where, {}); break;
        case ViewKind::fsm: page = fsm_page(text, where, &state.stopping); break;
        case ViewKind::handshake: page = handshake_page(text, where); break;
        case ViewKind::mission:
          throw InputError(where, "a mission trace is shown with its mission file: swarmcheck view TRACE --mission FILE");
      }
      res.set_content(assemble_page(page), "text/html; charset=utf-8");
    } catch (const InputError& e) {
      bad_request(res, 400, e.what());
    }
  });
  svr.Post("/api/validate", [&o](const httplib::Request& req, httplib::Response& res) {
    if (req.body.size() > o.body_bytes_max)
      return bad_request(res, 413, fmt::format("request body: expected at most {} bytes, got {}", o.body_bytes_max, req.body.size()));
    try {
      const exploration::Scenario s = exploration::parse_scenario(req.body, "request body");
      if (s.map_size > o.map_size_max)
        throw InputError("request body: map_size", fmt::format("expected at most {} for a live run, got {}", o.map_size_max, s.map_size));
      if (static_cast<int64_t>(s.robots.size()) > o.robots_max)
        throw InputError("request body: robots", fmt::format("expected at most {} robots for a live run, got {}", o.robots_max, s.robots.size()));
      res.set_content("{\"ok\": true}\n", "application/json");
    } catch (const InputError& e) {
      bad_request(res, 400, e.what());
    }
  });
}

// Who may ask (views/request_policy.hpp), decided before any body is read.
void refuse_strangers(httplib::Server& svr, const ServerIdentity& me) {
  svr.set_pre_routing_handler([&me](const httplib::Request& req, httplib::Response& res) {
    RequestHead head{req.method, req.path, {}, req.local_addr};
    for (const auto& [name, value] : req.headers) head.headers.emplace_back(name, value);
    const auto refusal = check_request_head(me, head);
    if (!refusal) return httplib::Server::HandlerResponse::Unhandled;
    bad_request(res, refusal->status, refusal->message);
    return httplib::Server::HandlerResponse::Handled;
  });
}

void error_pages(httplib::Server& svr, const ServeOptions& o) {
  svr.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr ep) {
    std::string what = "unknown";
    try { std::rethrow_exception(ep); } catch (const std::exception& e) { what = e.what(); } catch (...) {}
    res.status = 500;
    res.set_content("swarmcheck: internal error (please report): " + what + "\n", "text/plain");
  });
  svr.set_error_handler([&o](const httplib::Request& req, httplib::Response& res) {
    if (!res.body.empty()) return;
    // A path with a route for another method: 405 (httplib says 404, or 400 for PUT and DELETE).
    static const std::regex run_path(R"(/api/runs/[0-9a-f]{16}/(events|control))");
    const bool known_path = req.path == "/" || req.path == "/editor" || req.path == "/api/schema" || req.path == "/api/view" ||
                            req.path == "/api/validate" || req.path == "/api/runs" || std::regex_match(req.path, run_path);
    if ((res.status == 400 || res.status == 404) && known_path && req.method != "GET" && req.method != "POST") res.status = 405;
    std::string why;
    if (res.status == 404 || res.status == 405)
      why = fmt::format("no route {} {} (the routes: GET /, GET /editor, GET /api/schema, POST /api/view, POST /api/validate, "
                        "POST /api/runs, GET /api/runs/ID/events, POST /api/runs/ID/control)", req.method, req.path);
    else if (res.status == 413)
      why = fmt::format("the request body is larger than {} bytes, the most a request may send", o.view_bytes_max);
    res.set_content(fmt::format("swarmcheck: error: HTTP {}{}{}\n", res.status, why.empty() ? "" : ": ", why), "text/plain");
  });
}

ConnectionLimits connection_limits(const ServeOptions& o) {
  ConnectionLimits c;
  c.head_bytes_max = o.head_bytes_max;
  c.head_lines_max = o.head_lines_max;
  c.head_time_max = o.request_timeout;
  c.body_time_base = o.request_timeout;
  c.connections_max = o.connections_max;
  c.connections_per_client_max = o.connections_per_client;
  return c;
}

void say(const char* text) {
  const ssize_t ignored = ::write(STDERR_FILENO, text, std::strlen(text));
  (void)ignored;
}

}  // namespace serving

bool serve_available() { return true; }

int serve(const ServeOptions& o, const std::function<void(int port)>& on_listening) {
  if (o.port < 0 || o.port > 65535) throw InputError("--port", fmt::format("expected an integer in [0, 65535], got {}", o.port));
  // SIGINT and SIGTERM are blocked before anything is set up: one that comes while the server
  // starts waits for the waiter below and stops it as any other (it ended the process with the
  // command line's 130 before). A failed start unblocks them again.
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  sigset_t before;
  pthread_sigmask(SIG_BLOCK, &set, &before);
  struct RestoreMask {
    sigset_t mask;
    bool keep = false;
    ~RestoreMask() {
      if (!keep) pthread_sigmask(SIG_SETMASK, &mask, nullptr);
    }
  } restore{before};
  ServeState state(o);   // outlives the server and its threads (the streams' releasers use it)
  ServerIdentity me{o.bind, o.port, o.allowed_hosts};
  GuardedServer svr(serving::connection_limits(o), state.stopping);
  svr.new_task_queue = [] { return new ConnectionThreads; };   // a thread per connection (a slow one holds its own)
  svr.set_payload_max_length(o.view_bytes_max);   // scenarios are held to body_bytes_max
  svr.set_default_headers(security_headers());     // nosniff, frame-ancestors 'none', ... on every response
  serving::error_pages(svr, o);
  serving::refuse_strangers(svr, me);
  serving::page_routes(svr, state);
  RunRoutes runs(svr, state);
  int port = o.port;
  if (port == 0) {
    port = svr.bind_to_any_port(o.bind);
    if (port < 0) throw InputError("--bind", "cannot listen on " + o.bind);
  } else if (!svr.bind_to_port(o.bind, port)) {
    throw InputError("--port", fmt::format("cannot listen on {}:{} (in use, or not an address of this machine)", o.bind, port));
  }
  me.port = port;
  // SIGINT / SIGTERM stop the server from a thread of its own (stop() is not signal-safe). Every
  // wait of every connection looks at `stopping` at least every 100 ms, dot is killed, and the
  // listening loop ends; if that has not happened within a second (a view still being built) or
  // a second signal comes, the process ends at once, its temporary files removed.
  restore.keep = true;   // the waiter owns the signals from here
  ::signal(SIGPIPE, SIG_IGN);
  std::mutex mutex;
  std::condition_variable ended;
  bool finished = false, signalled = false;
  std::thread waiter([&] {
    int sig = 0;
    sigwait(&set, &sig);
    {
      std::lock_guard lock(mutex);
      if (finished) return;   // woken by serve() itself: the loop ended on its own
      signalled = true;
    }
    state.stopping = true;
    svr.stop();
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(900);
    for (;;) {
      {
        std::unique_lock lock(mutex);
        if (ended.wait_for(lock, std::chrono::milliseconds(50), [&] { return finished; })) return;
      }
      const timespec now{0, 0};
      if (sigtimedwait(&set, nullptr, &now) > 0 || std::chrono::steady_clock::now() >= deadline) break;
    }
    serving::say("swarmcheck serve: stopped with a request unfinished\n");
    impl::io::remove_temp_files_now();
    ::_exit(0);
  });
  on_listening(port);
  svr.listen_after_bind();
  bool wake = false;
  {
    std::lock_guard lock(mutex);
    finished = true;
    wake = !signalled;
  }
  ended.notify_all();
  if (wake) pthread_kill(waiter.native_handle(), SIGTERM);   // no signal came: end its wait
  waiter.join();
  return 0;
}

}  // namespace swarmcheck::views

#else

namespace swarmcheck::views {
bool serve_available() { return false; }
int serve(const ServeOptions&, const std::function<void(int)>&) {
  throw InputError("serve", "this swarmcheck was built without cpp-httplib (Debian: apt-get install libcpp-httplib-dev, then rebuild)");
}
}  // namespace swarmcheck::views

#endif
