#pragma once
// Counterexample traces of the handshake obligations, JSON Lines:
//   {"format":"swarmcheck-trace","format_version":1,"system":"handshake","obligation":NAME,
//    "robots":N,"master":"jacobi"|"gauss-seidel","controller":"spec"|"late"}
// then one object per master step t: the Environment's state at the start of the step
// ("flag", "onDestinationOutput"), whether it plans in the step ("plan"), each controller's
// onDestinationOutput at the start of the step (a late controller's: the value on its port,
// one step old), "arrival": whether its robot is at its waypoint in the step (by its pose),
// whether it accepts a waypoint in the step, whether its robot has reached its issued waypoint
// (ghost "reached", at the start of the step), the pose ("x", "y", "theta") and the waypoint
// ("xDesired", "yDesired") in the step, and "violated": the property the step breaks, on that
// step only. A trace carries the controller parameters it was found with ("tolerance",
// "orient_tolerance", "reorient") in its header.
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace swarmcheck::proofs::handshake {

struct TraceController {
  int32_t on_destination_output = 0;
  bool arrival = false;
  bool accepted = false;
  bool reached = false;
  double x_m = 0, y_m = 0, theta_rad = 0, x_desired_m = 0.5, y_desired_m = 0.5;
};

struct TraceStep {
  int64_t step = 0;
  int32_t flag = 0;
  int32_t on_destination_output = 0;
  bool plan = false;
  std::vector<TraceController> controllers;
  std::string violated;   // empty: none
};

struct HandshakeTrace {
  std::string obligation;
  int32_t robots = 0;
  std::string master;       // "jacobi" or "gauss-seidel"
  std::string controller;   // "spec" or "late"
  double tolerance_m = 0.05, orient_tolerance_rad = 0.01, reorient_rad = 0.2;
  std::vector<TraceStep> steps;
};

std::string write_handshake_trace(const HandshakeTrace& t);

// Reads a trace file; throws swarmcheck::InputError naming file:line for a malformed one.
HandshakeTrace read_handshake_trace(const std::string& path);

// Prints the trace step by step as a table (for `swarmcheck replay`); returns 0.
// Throws swarmcheck::InputError naming file:line for a malformed trace.
int show_handshake_trace(const std::string& path, std::FILE* out);

}  // namespace swarmcheck::proofs::handshake
