// The live runs of `swarmcheck serve`: started by POST /api/runs, streamed to their page as
// Server-Sent Events, paused or sped up by POST /api/runs/ID/control. At most runs_max at once
// and runs_per_client for one client address (429 past either).
#include "views/server_state.hpp"

#ifdef SWARMCHECK_HAVE_HTTPLIB

#include <fmt/format.h>

#include <chrono>
#include <map>
#include <mutex>
#include <random>
#include <thread>

#include "spec/exploration/scenario.hpp"
#include "spec/exploration/trace_field.hpp"
#include "spec/util/input_error.hpp"
#include "spec/util/json_text.hpp"
#include "swarmcheck/exploration.hpp"

namespace swarmcheck::views {
namespace live {   // named: views/ is a unity build

using json_io::Json;
using namespace swarmcheck::exploration;
using Clock = std::chrono::steady_clock;

constexpr int64_t kStepsPerFrameMax = 100'000;
constexpr std::size_t kControlBytesMax = 4096;

struct LiveRun {
  Scenario scenario;
  std::string client;   // the address that started it
  std::atomic<bool> paused{false};
  std::atomic<int64_t> steps_per_frame{100};
  std::atomic<bool> claimed{false};   // its stream has been opened (once only)
  Clock::time_point created = Clock::now();
};

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

}  // namespace live

struct RunRoutes::Registry {
  explicit Registry(const ServeOptions& o) : o_(o) {}

  // The new run's id, or why there is none (runs_max runs, or runs_per_client of its client).
  std::string add(std::shared_ptr<live::LiveRun> run, std::string& refused) {
    std::lock_guard lock(mutex_);
    drop_unclaimed();
    if (static_cast<int>(runs_.size()) >= o_.runs_max) {
      refused = fmt::format("{} runs are going on already (the limit); close a page and retry", o_.runs_max);
      return {};
    }
    int mine = 0;
    for (const auto& [id, r] : runs_) mine += r->client == run->client ? 1 : 0;
    if (mine >= o_.runs_per_client) {
      refused = fmt::format("{} runs of this client ({}) are going on already (the limit for one client); close a page and retry",
                            mine, run->client);
      return {};
    }
    const std::string id = fmt::format("{:016x}", rng_());
    runs_[id] = std::move(run);
    return id;
  }
  std::shared_ptr<live::LiveRun> find(const std::string& id) {
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
      const bool stale = !it->second->claimed && live::Clock::now() - it->second->created > std::chrono::seconds(o_.unclaimed_run_s);
      it = stale ? runs_.erase(it) : std::next(it);
    }
  }
  const ServeOptions& o_;
  std::mutex mutex_;
  std::map<std::string, std::shared_ptr<live::LiveRun>> runs_;
  std::mt19937_64 rng_{std::random_device{}()};
};

namespace live {

// The stream of one run: each call of the provider computes and sends one frame.
void stream(httplib::Response& res, std::shared_ptr<LiveRun> run, const std::string& id, RunRoutes::Registry& registry,
            const ServeState& state) {
  auto x = std::make_shared<Exploration>(run->scenario);
  const int64_t cells = int64_t{run->scenario.map_size} * run->scenario.map_size;
  const int64_t field_every = cells <= 4096 ? 1 : 10;
  auto frames = std::make_shared<int64_t>(0);
  res.set_header("Cache-Control", "no-store");
  res.set_chunked_content_provider(
      "text/event-stream",
      [run, x, frames, field_every, &state](std::size_t, httplib::DataSink& sink) {
        if (state.stopping || !sink.is_writable()) return false;
        if (run->paused) {
          std::this_thread::sleep_for(std::chrono::milliseconds(state.o.frame_ms));
          return sink.write(": paused\n\n", 10);
        }
        const auto start = Clock::now();
        const int64_t n = *frames == 0 ? 0 : run->steps_per_frame.load();   // frame 0: the start
        // At most n steps; a frame also ends when its page has gone, the run is paused or the
        // server stops, checked every 16 steps, and after a second of steps (shown as far as it
        // got): 100 000 steps of 4 096 robots kept a closed page's run computing for half a minute.
        for (int64_t k = 0; k < n && !x->done(); ++k) {
          x->step();
          if ((k & 15) == 15 && (state.stopping || run->paused || !sink.is_writable() || Clock::now() - start > std::chrono::seconds(1)))
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
        std::this_thread::sleep_until(start + std::chrono::milliseconds(state.o.frame_ms));
        return true;
      },
      [id, &registry](bool) { registry.remove(id); });
}

}  // namespace live

RunRoutes::RunRoutes(httplib::Server& svr, ServeState& state) : registry_(std::make_unique<Registry>(state.o)) {
  Registry& registry = *registry_;
  const ServeOptions& o = state.o;
  svr.Post("/api/runs", [&o, &registry](const httplib::Request& req, httplib::Response& res) {
    if (live::too_big(req, res, o.body_bytes_max)) return;
    auto run = std::make_shared<live::LiveRun>();
    run->client = req.remote_addr;
    try {
      run->scenario = live::request_scenario(req, o);
      if (req.has_param("steps_per_frame")) {
        const std::string v = req.get_param_value("steps_per_frame");
        int64_t n = 0;
        try { n = std::stoll(v); } catch (const std::exception&) { n = 0; }
        if (n < 1 || n > live::kStepsPerFrameMax || std::to_string(n) != v)
          throw InputError("steps_per_frame", fmt::format("expected an integer in [1, {}], got \"{}\"", live::kStepsPerFrameMax, v));
        run->steps_per_frame = n;
      }
    } catch (const InputError& e) {
      return bad_request(res, 400, e.what());
    }
    std::string refused;
    const std::string id = registry.add(run, refused);
    if (id.empty()) return bad_request(res, 429, refused);
    res.status = 201;
    res.set_content(live::Json{{"id", id}, {"scenario", json_io::to_json(run->scenario)}}.dump(), "application/json");
  });
  svr.Get(R"(/api/runs/([0-9a-f]{16})/events)", [&state, &registry](const httplib::Request& req, httplib::Response& res) {
    const std::string id = req.matches[1];
    const auto run = registry.find(id);
    if (!run) return bad_request(res, 404, "no run " + id + " (finished, stopped or never started)");
    if (run->claimed.exchange(true)) return bad_request(res, 409, "run " + id + " is already being watched");
    live::stream(res, run, id, registry, state);
  });
  svr.Post(R"(/api/runs/([0-9a-f]{16})/control)", [&registry](const httplib::Request& req, httplib::Response& res) {
    const auto run = registry.find(req.matches[1]);
    if (!run) return bad_request(res, 404, "no run " + std::string(req.matches[1]));
    if (live::too_big(req, res, live::kControlBytesMax)) return;
    live::Json j;
    try {
      j = json_io::parse_json_text(req.body, "request body");
      if (!j.is_object()) throw InputError("request body: (top level)", "expected an object");
    } catch (const InputError& e) {
      return bad_request(res, 400, e.what());
    }
    try {
      json_io::refuse_unknown_keys(j, "", {"paused", "steps_per_frame"});
    } catch (const InputError& e) {
      return bad_request(res, 400, std::string("request body: ") + e.what());
    }
    for (const auto& [key, value] : j.items()) {
      if (key == "paused" && value.is_boolean()) continue;
      if (key == "steps_per_frame" && value.is_number_integer() && value.get<int64_t>() >= 1 && value.get<int64_t>() <= live::kStepsPerFrameMax) continue;
      return bad_request(res, 400, fmt::format("request body: {}: expected \"paused\": a boolean or \"steps_per_frame\": an integer in [1, {}]", key, live::kStepsPerFrameMax));
    }
    if (j.contains("paused")) run->paused = j["paused"].get<bool>();
    if (j.contains("steps_per_frame")) run->steps_per_frame = j["steps_per_frame"].get<int64_t>();
    res.status = 204;
  });
}

RunRoutes::~RunRoutes() = default;

}  // namespace swarmcheck::views

#endif
