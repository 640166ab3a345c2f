#pragma once
// `swarmcheck serve`: the live page, the editor, and runs streamed to the page.
//
//   GET  /                         the live page (scenario editor + Run)
//   GET  /editor                   the scenario editor alone
//   GET  /api/schema               the scenario JSON Schema
//   POST /api/view                 body: {"name": FILE NAME, "text": a trace or an .fsm file}; 200 the
//                                  view page, or 400 (messages name the file); 429 past views_max
//   POST /api/validate             body: a scenario; 200 {"ok": true} or 400 with the CLI's message
//   POST /api/runs[?steps_per_frame=N]   body: a scenario; 201 {"id", "scenario"}; 400 / 413 / 429
//   GET  /api/runs/ID/events       Server-Sent Events: "step" frames as the run computes them,
//                                  then "done"; the run stops when the page goes away
//   POST /api/runs/ID/control      body: {"paused": bool, "steps_per_frame": N}; 204
//
// Every request is checked like a file input: bad input gets HTTP 4xx and the message the CLI
// gives for the same file ("swarmcheck: error: request body: robots[1]: ..."). Who may ask is
// views/request_policy.hpp's (Host, Origin, Content-Type: 403 / 415), how long and how much a
// connection may send views/http_connection.hpp's (408 / 431 / 503). Limits on everything:
// request bodies, maps and robots of a live run, runs at once and per client, views being built
// at once (each may run dot), and a run's memory (one frame is built, sent and dropped at a time,
// so a slow page slows its run, nothing queues). SIGINT or SIGTERM stops it within a second
// whatever the clients do.
#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace swarmcheck::views {

struct ServeOptions {
  std::string bind = "127.0.0.1";
  int port = 8080;                     // 0: any free port (printed)
  std::vector<std::string> allowed_hosts;   // --allow-host: Host names besides loopback and the bound address
  int runs_max = 8;                    // runs streaming or waiting at once
  int runs_per_client = 4;             // ... of one client address
  int views_max = 2;                   // POST /api/view answered at once (each may run dot for 20 s)
  int32_t map_size_max = 512;          // a live run's map, at most
  int64_t robots_max = 4096;
  std::size_t body_bytes_max = 1 << 20;     // a scenario or a control request
  std::size_t view_bytes_max = 64 << 20;    // a trace posted to /api/view (and any request)
  int frame_ms = 50;                   // one frame every 50 ms at most
  int unclaimed_run_s = 30;            // a run whose stream never opens is dropped after this
  // Connections (views/http_connection.hpp's ConnectionLimits): a request's head must arrive
  // within request_timeout of its connection, its body within request_timeout and a second per
  // MiB more; heads are at most head_bytes_max bytes and head_lines_max lines.
  std::chrono::milliseconds request_timeout{10'000};
  std::size_t head_bytes_max = 32 << 10;
  int head_lines_max = 100;
  int connections_max = 64;
  int connections_per_client = 16;
};

bool serve_available();   // built with cpp-httplib

// Listens until SIGINT or SIGTERM; on_listening(port) once bound. Returns the exit status.
int serve(const ServeOptions& o, const std::function<void(int port)>& on_listening);

}  // namespace swarmcheck::views
