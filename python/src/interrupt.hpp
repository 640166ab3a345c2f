#pragma once
// Ctrl-C during a long call that released the GIL. Python's own SIGINT handler only sets a flag
// that the interpreter acts on between bytecodes, so a loop in C++ asks for it: every 50 ms (the
// clock read every 64 steps, a few ns a step) the loop takes the GIL back and calls
// PyErr_CheckSignals, which runs the handler; when that raises (KeyboardInterrupt), the loop stops
// by throwing Interrupted, and the caller re-raises the Python error once it holds the GIL again.
#include <pybind11/pybind11.h>

#include <chrono>
#include <cstdint>

namespace swarmcheck::python {

struct Interrupted {};

class SignalPoll {
 public:
  // The clock is read every `every` calls (a step: 64; a construction's budget check, made every
  // few thousand states: 1).
  explicit SignalPoll(uint64_t every = 64) : every_(every) {}
  // Called after every step (or check), the GIL released.
  void operator()() {
    if (++calls_ % every_ != 0) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::milliseconds(50)) return;
    last_ = now;
    pybind11::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw Interrupted{};   // the error stays set for the caller
  }

 private:
  uint64_t every_;
  uint64_t calls_ = 0;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

// Runs f() with the GIL released, polling for signals through the SignalPoll it is given; a
// signal handler's exception (KeyboardInterrupt) is raised from here, with the GIL held.
template <class F>
auto without_gil(F&& f, uint64_t every = 64) {
  SignalPoll poll(every);
  try {
    pybind11::gil_scoped_release release;
    return f(poll);
  } catch (const Interrupted&) {
    throw pybind11::error_already_set();
  }
}

}  // namespace swarmcheck::python
