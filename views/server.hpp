#pragma once
// `swarmcheck serve`: the live page, the editor, and runs streamed to the page.
//
//   GET  /                         the live page (scenario editor + Run)
//   GET  /editor                   the scenario editor alone
//   GET  /api/schema               the scenario JSON Schema
//   POST /api/view                 body: a trace or an .fsm file; 200 the view page, or 400
//   POST /api/validate             body: a scenario; 200 {"ok": true} or 400 with the CLI's message
//   POST /api/runs[?steps_per_frame=N]   body: a scenario; 201 {"id", "scenario"}; 400 / 413 / 429
//   GET  /api/runs/ID/events       Server-Sent Events: "step" frames as the run computes them,
//                                  then "done"; the run stops when the page goes away
//   POST /api/runs/ID/control      body: {"paused": bool, "steps_per_frame": N}; 204
//
// Every request is checked like a file input: bad input gets HTTP 4xx and the message the CLI
// gives for the same file ("swarmcheck: error: request body: robots[1]: ..."). Limits on
// everything: request bodies, maps and robots of a live run, runs at once, and a run's memory
// (one frame is built, sent and dropped at a time, so a slow page slows its run, nothing queues).
#include <cstdint>
#include <functional>
#include <string>

namespace swarmcheck::views {

struct ServeOptions {
  std::string bind = "127.0.0.1";
  int port = 8080;                     // 0: any free port (printed)
  int runs_max = 8;                    // runs streaming or waiting at once
  int32_t map_size_max = 512;          // a live run's map, at most
  int64_t robots_max = 4096;
  std::size_t body_bytes_max = 1 << 20;     // a scenario or a control request
  std::size_t view_bytes_max = 64 << 20;    // a trace posted to /api/view (and any request)
  int frame_ms = 50;                   // one frame every 50 ms at most
  int unclaimed_run_s = 30;            // a run whose stream never opens is dropped after this
};

bool serve_available();   // built with cpp-httplib

// Listens until SIGINT or SIGTERM; on_listening(port) once bound. Returns the exit status.
int serve(const ServeOptions& o, const std::function<void(int port)>& on_listening);

}  // namespace swarmcheck::views
