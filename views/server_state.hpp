#pragma once
// What the parts of `swarmcheck serve` share (views/server.cpp: the server, its page routes and
// its stop; views/live_runs.cpp: the runs and their streams). Inside views/ only.
#ifdef SWARMCHECK_HAVE_HTTPLIB

#include <httplib.h>

#include <atomic>
#include <memory>
#include <string>

#include "views/server.hpp"

namespace swarmcheck::views {

struct ServeState {
  explicit ServeState(const ServeOptions& options) : o(options) {}
  const ServeOptions& o;
  std::atomic<bool> stopping{false};   // set by SIGINT / SIGTERM: streams end, dot is killed
  std::atomic<int> views_building{0};  // POST /api/view requests being answered (at most views_max)
};

// 4xx with "swarmcheck: error: <message>" as text.
void bad_request(httplib::Response& res, int status, const std::string& message);

// POST /api/runs, GET /api/runs/ID/events, POST /api/runs/ID/control; the registry of runs
// lives as long as the server's threads (it is created inside).
class RunRoutes {
 public:
  RunRoutes(httplib::Server& svr, ServeState& state);
  ~RunRoutes();
  RunRoutes(const RunRoutes&) = delete;
  RunRoutes& operator=(const RunRoutes&) = delete;

 struct Registry;   // the runs going on

 private:
  std::unique_ptr<Registry> registry_;
};

}  // namespace swarmcheck::views

#endif
