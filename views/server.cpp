#include "views/server.hpp"

#include "spec/util/input_error.hpp"

#ifdef SWARMCHECK_HAVE_HTTPLIB

#include <httplib.h>
#include <signal.h>

#include <atomic>
#include <chrono>
#include <regex>
#include <fmt/format.h>
#include <map>
#include <memory>
#include <mutex>
#include <random>
#include <thread>

#include "spec/exploration/neighbourhood.hpp"
#include "spec/exploration/scenario.hpp"
#include "spec/exploration/trace_field.hpp"
#include "swarmcheck/exploration.hpp"
#include "views/edit.hpp"
#include "views/schema.hpp"
#include "views/view.hpp"

namespace swarmcheck::views {
namespace {

using json_io::Json;
using namespace swarmcheck::exploration;
using Clock = std::chrono::steady_clock;

constexpr int64_t kStepsPerFrameMax = 100'000;
std::atomic<bool> g_stopping{false};   // the server is shutting down: streams end at once

struct LiveRun {
  Scenario scenario;
  std::atomic<bool> paused{false};
  std::atomic<int64_t> steps_per_frame{100};
  std::atomic<bool> claimed{false};   // its stream has been opened (once only)
  Clock::time_point created = Clock::now();
};

class Registry {
 public:
  explicit Registry(const ServeOptions& o) : o_(o) {}

  // The new run's id, or empty when runs_max are already there.
  std::string add(std::shared_ptr<LiveRun> run) {
    std::lock_guard lock(mutex_);
    drop_unclaimed();
    if (static_cast<int>(runs_.size()) >= o_.runs_max) return {};
    const std::string id = fmt::format("{:016x}", rng_());
    runs_[id] = std::move(run);
    return id;
  }
  std::shared_ptr<LiveRun> find(const std::string& id) {
    std::lock_guard lock(mutex_);
    const auto it = runs_.find(id);
    return it == runs_.end() ? nullptr : it->second;
  }
  void remove(const std::string& id) {
    std::lock_guard lock(mutex_);
    runs_.erase(id);
  }

 private:
  void drop_unclaimed() {
    for (auto it = runs_.begin(); it != runs_.end();) {
      const bool stale = !it->second->claimed && Clock::now() - it->second->created > std::chrono::seconds(o_.unclaimed_run_s);
      it = stale ? runs_.erase(it) : std::next(it);
    }
  }
  const ServeOptions& o_;
  std::mutex mutex_;
  std::map<std::string, std::shared_ptr<LiveRun>> runs_;
  std::mt19937_64 rng_{std::random_device{}()};
};

void bad_request(httplib::Response& res, int status, const std::string& message) {
  res.status = status;
  res.set_content("swarmcheck: error: " + message + "\n", "text/plain; charset=utf-8");
}

// Scenarios and controls are small: a body above the limit is refused before it is read as JSON.
bool too_big(const httplib::Request& req, httplib::Response& res, std::size_t max) {
  if (req.body.size() <= max) return false;
  bad_request(res, 413, fmt::format("request body: expected at most {} bytes, got {}", max, req.body.size()));
  return true;
}

// The scenario of a request body, checked as `run` checks a file, then against the live limits.
Scenario request_scenario(const httplib::Request& req, const ServeOptions& o) {
  const Scenario s = parse_scenario(req.body, "request body");
  if (s.map_size > o.map_size_max)
    throw InputError("request body: map_size", fmt::format("expected at most {} for a live run, got {}", o.map_size_max, s.map_size));
  if (static_cast<int64_t>(s.robots.size()) > o.robots_max)
    throw InputError("request body: robots", fmt::format("expected at most {} robots for a live run, got {}", o.robots_max, s.robots.size()));
  return s;
}

std::string frame(const Exploration& x, bool with_field) {
  const Scenario& s = x.scenario();
  Json robots = Json::array();
  const auto bodies = x.bodies();
  const auto env = x.robots();   // the cell and the waypoint the Environment issued
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    const CellIndex c = env[k].cell;
    const Point_m w = env[k].waypoint;
    robots.push_back({bodies[k].x_m, bodies[k].y_m, bodies[k].theta_rad, c[0], c[1], w[0], w[1]});
  }
  Json j = {{"step", x.steps()}, {"eP", x.eP()}, {"sTime", x.sTime()}, {"visited", x.visited()},
            {"free_cells", x.free_cells()}, {"robots", robots}};
  if (with_field) {
    FieldSnapshot f;
    f.step = x.steps();
    f.map_size = s.map_size;
    const std::size_t n = static_cast<std::size_t>(s.map_size);
    f.pheromone.resize(n * n);
    f.visited.resize(n * n);
    for (int32_t i = 0; i < s.map_size; ++i)
      for (int32_t jj = 0; jj < s.map_size; ++jj) {
        const Cell c = x.cell({i, jj});
        f.pheromone[static_cast<std::size_t>(i) * n + static_cast<std::size_t>(jj)] = c.pheromone;
        f.visited[static_cast<std::size_t>(i) * n + static_cast<std::size_t>(jj)] = c.visited;
      }
    Json fj = field_record(f);
    fj.erase("digest");   // a u64: JavaScript cannot hold it, and the page does not need it
    j["field"] = fj;
  }
  return "event: step\ndata: " + j.dump() + "\n\n";
}

std::string done_frame(const Exploration& x) {
  const auto c = x.completion_step();
  Json j = {{"completed", c.has_value()}, {"completion_step", c ? Json(*c) : Json(nullptr)}, {"steps", x.steps()},
            {"eP", x.eP()}, {"sTime", x.sTime()}, {"visited", x.visited()}, {"free_cells", x.free_cells()}};
  return "event: done\ndata: " + j.dump() + "\n\n";
}

// The stream of one run: each call of the provider computes and sends one frame.
void stream(httplib::Response& res, std::shared_ptr<LiveRun> run, const std::string& id, Registry& registry, const ServeOptions& o) {
  auto x = std::make_shared<Exploration>(run->scenario);
  const int64_t cells = int64_t{run->scenario.map_size} * run->scenario.map_size;
  const int64_t field_every = cells <= 4096 ? 1 : 10;
  auto frames = std::make_shared<int64_t>(0);
  res.set_header("Cache-Control", "no-store");
  res.set_chunked_content_provider(
      "text/event-stream",
      [run, x, frames, field_every, &o](std::size_t, httplib::DataSink& sink) {
        if (g_stopping || !sink.is_writable()) return false;
        if (run->paused) {
          std::this_thread::sleep_for(std::chrono::milliseconds(o.frame_ms));
          return sink.write(": paused\n\n", 10);
        }
        const auto start = Clock::now();
        const int64_t n = *frames == 0 ? 0 : run->steps_per_frame.load();   // frame 0: the start
        // At most n steps; a frame also ends when its page has gone, the run is paused or the
        // server stops, checked every 16 steps, and after a second of steps (shown as far as it
        // got): 100 000 steps of 4 096 robots kept a closed page's run computing for half a minute.
        for (int64_t k = 0; k < n && !x->done(); ++k) {
          x->step();
          if ((k & 15) == 15 && (g_stopping || run->paused || !sink.is_writable() || Clock::now() - start > std::chrono::seconds(1)))
            break;
        }
        const std::string f = frame(*x, *frames % field_every == 0 || x->done());
        ++*frames;
        if (!sink.write(f.data(), f.size())) return false;
        if (x->done()) {
          const std::string d = done_frame(*x);
          if (!sink.write(d.data(), d.size())) return false;
          sink.done();
          return true;
        }
        std::this_thread::sleep_until(start + std::chrono::milliseconds(o.frame_ms));
        return true;
      },
      [id, &registry](bool) { registry.remove(id); });
}

void page_routes(httplib::Server& svr, const ServeOptions& o) {
  svr.Get("/", [](const httplib::Request&, httplib::Response& res) {
    res.set_content(assemble_page(live_page()), "text/html; charset=utf-8");
  });
  svr.Get("/editor", [](const httplib::Request&, httplib::Response& res) {
    res.set_content(assemble_page(scenario_editor_page("")), "text/html; charset=utf-8");
  });
  svr.Get("/api/schema", [](const httplib::Request&, httplib::Response& res) {
    res.set_content(scenario_schema().dump(2), "application/json");
  });
  // A trace or an .fsm file posted by the page: the view `swarmcheck view` would write. A mission
  // trace needs its mission file, which the server does not read: that one is `view`'s.
  svr.Post("/api/view", [](const httplib::Request& req, httplib::Response& res) {
    try {
      const std::string where = "request body";
      Page page;
      switch (detect_view_kind(req.body, where)) {
        case ViewKind::exploration:
        case ViewKind::counterexample: page = exploration_page(req.body, where, {}); break;
        case ViewKind::fsm: page = fsm_page(req.body, where); break;
        case ViewKind::handshake: page = handshake_page(req.body, where); break;
        case ViewKind::mission:
          throw InputError(where, "a mission trace is shown with its mission file: swarmcheck view TRACE --mission FILE");
      }
      res.set_content(assemble_page(page), "text/html; charset=utf-8");
    } catch (const InputError& e) {
      bad_request(res, 400, e.what());
    }
  });
  svr.Post("/api/validate", [&o](const httplib::Request& req, httplib::Response& res) {
    if (too_big(req, res, o.body_bytes_max)) return;
    try {
      request_scenario(req, o);
      res.set_content("{\"ok\": true}\n", "application/json");
    } catch (const InputError& e) {
      bad_request(res, 400, e.what());
    }
  });
}

void run_routes(httplib::Server& svr, Registry& registry, const ServeOptions& o) {
  svr.Post("/api/runs", [&o, &registry](const httplib::Request& req, httplib::Response& res) {
    if (too_big(req, res, o.body_bytes_max)) return;
    auto run = std::make_shared<LiveRun>();
    try {
      run->scenario = request_scenario(req, o);
      if (req.has_param("steps_per_frame")) {
        const std::string v = req.get_param_value("steps_per_frame");
        int64_t n = 0;
        try { n = std::stoll(v); } catch (const std::exception&) { n = 0; }
        if (n < 1 || n > kStepsPerFrameMax || std::to_string(n) != v)
          throw InputError("steps_per_frame", fmt::format("expected an integer in [1, {}], got \"{}\"", kStepsPerFrameMax, v));
        run->steps_per_frame = n;
      }
    } catch (const InputError& e) {
      return bad_request(res, 400, e.what());
    }
    const std::string id = registry.add(run);
    if (id.empty()) return bad_request(res, 429, fmt::format("{} runs are going on already (the limit); close a page and retry", o.runs_max));
    res.status = 201;
    res.set_content(Json{{"id", id}, {"scenario", json_io::to_json(run->scenario)}}.dump(), "application/json");
  });
  svr.Get(R"(/api/runs/([0-9a-f]{16})/events)", [&o, &registry](const httplib::Request& req, httplib::Response& res) {
    const std::string id = req.matches[1];
    const auto run = registry.find(id);
    if (!run) return bad_request(res, 404, "no run " + id + " (finished, stopped or never started)");
    if (run->claimed.exchange(true)) return bad_request(res, 409, "run " + id + " is already being watched");
    stream(res, run, id, registry, o);
  });
  svr.Post(R"(/api/runs/([0-9a-f]{16})/control)", [&registry](const httplib::Request& req, httplib::Response& res) {
    const auto run = registry.find(req.matches[1]);
    if (!run) return bad_request(res, 404, "no run " + std::string(req.matches[1]));
    if (too_big(req, res, 4096)) return;
    Json j;
    try {
      j = Json::parse(req.body);
    } catch (const nlohmann::json::parse_error&) {
      return bad_request(res, 400, "request body: not valid JSON");
    }
    if (!j.is_object()) return bad_request(res, 400, "request body: (top level): expected an object");
    for (const auto& [key, value] : j.items()) {
      if (key == "paused" && value.is_boolean()) continue;
      if (key == "steps_per_frame" && value.is_number_integer() && value.get<int64_t>() >= 1 && value.get<int64_t>() <= kStepsPerFrameMax) continue;
      return bad_request(res, 400, fmt::format("request body: {}: expected \"paused\": a boolean or \"steps_per_frame\": an integer in [1, {}]", key, kStepsPerFrameMax));
    }
    if (j.contains("paused")) run->paused = j["paused"].get<bool>();
    if (j.contains("steps_per_frame")) run->steps_per_frame = j["steps_per_frame"].get<int64_t>();
    res.status = 204;
  });
}

}  // namespace

bool serve_available() { return true; }

int serve(const ServeOptions& o, const std::function<void(int port)>& on_listening) {
  if (o.port < 0 || o.port > 65535) throw InputError("--port", fmt::format("expected an integer in [0, 65535], got {}", o.port));
  Registry registry(o);   // outlives the server and its threads (the streams' releasers use it)
  httplib::Server svr;
  const int threads = o.runs_max + 4;   // every stream holds a thread; requests keep 4
  svr.new_task_queue = [threads] { return new httplib::ThreadPool(static_cast<std::size_t>(threads)); };
  svr.set_payload_max_length(o.view_bytes_max);   // scenarios are held to body_bytes_max
  svr.set_read_timeout(10, 0);
  svr.set_write_timeout(10, 0);
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
    else if (res.status == 413 && req.get_header_value("Content-Type").starts_with("application/x-www-form-urlencoded"))
      // Debian's compiled cpp-httplib holds a form body (curl's default type for --data) to 8 KiB.
      why = "a body sent as a form (application/x-www-form-urlencoded, curl's default for --data) may not exceed 8 KiB: "
            "send it as JSON or text (curl -H 'Content-Type: application/json')";
    else if (res.status == 413)
      why = fmt::format("the request body is larger than {} bytes, the most a request may send", o.view_bytes_max);
    res.set_content(fmt::format("swarmcheck: error: HTTP {}{}{}\n", res.status, why.empty() ? "" : ": ", why), "text/plain");
  });
  page_routes(svr, o);
  run_routes(svr, registry, o);
  int port = o.port;
  if (port == 0) {
    port = svr.bind_to_any_port(o.bind);
    if (port < 0) throw InputError("--bind", "cannot listen on " + o.bind);
  } else if (!svr.bind_to_port(o.bind, port)) {
    throw InputError("--port", fmt::format("cannot listen on {}:{} (in use, or not an address of this machine)", o.bind, port));
  }
  // SIGINT / SIGTERM stop the server from a thread of its own (stop() is not signal-safe).
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
  ::signal(SIGPIPE, SIG_IGN);
  std::thread waiter([&svr, set] {
    int sig = 0;
    sigwait(&set, &sig);
    g_stopping = true;
    svr.stop();
  });
  on_listening(port);
  svr.listen_after_bind();
  pthread_kill(waiter.native_handle(), SIGTERM);
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
