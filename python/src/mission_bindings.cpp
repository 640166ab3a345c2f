// swarmcheck.mission_plan / mission_run: a mission file planned and run by the library, the dicts
// of `swarmcheck mission plan|run --json` (swarmcheck/mission_report.hpp).
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

#include "python/src/bindings.hpp"
#include "python/src/interrupt.hpp"
#include "python/src/json_convert.hpp"
#include "swarmcheck/mission.hpp"
#include "swarmcheck/mission_report.hpp"

namespace py = pybind11;
namespace sm = swarmcheck::mission;

namespace swarmcheck::python {
namespace {

std::string path_of(const py::object& p) {
  return py::module_::import("os").attr("fspath")(p).cast<std::string>();
}

// The checks of `mission run`'s flags (CLI11 ranges there), naming the keyword.
void check_range(double v, double lo, double hi, const char* name, const char* what) {
  if (!(v >= lo && v <= hi)) throw InputError(name, std::string("expected ") + what);
}

// Forwards to the trace (if any) and looks for Ctrl-C after every step, the GIL released.
class MissionObserver final : public sm::RunObserver {
 public:
  MissionObserver(sm::TraceFile* trace, SignalPoll& poll) : trace_(trace), poll_(poll) {}
  void on_event(const sm::EventRecord& e) override {
    if (trace_) trace_->on_event(e);
  }
  void on_step(const sm::StepRecord& s) override {
    if (trace_) trace_->on_step(s);
    poll_();
  }
  void on_interval(const sm::IntervalRecord& i) override {
    if (trace_) trace_->on_interval(i);
  }

 private:
  sm::TraceFile* trace_;
  SignalPoll& poll_;
};

}  // namespace

void bind_mission(py::module_& m) {
  m.def(
      "mission_plan",
      [](const py::object& mission, const std::optional<std::string>& from_state) {
        const std::string file = path_of(mission);
        const sm::Mission ms = sm::load_mission(file);
        const std::string from = from_state.value_or(ms.initial_state);
        if (std::find(ms.fsm.states.begin(), ms.fsm.states.end(), from) == ms.fsm.states.end())
          throw InputError("from_state", "state \"" + from + "\" is not in " + ms.fsm_name);
        const sm::PlanQuery q = sm::query_from(ms, from);
        sm::Plan p;
        {
          py::gil_scoped_release release;
          sm::Planner planner(ms);
          p = planner.plan(q);
        }
        return to_python(sm::mission_plan_report(ms, p, file, "exact", from));
      },
      py::arg("mission"), py::arg("from_state") = py::none(),
      R"(`swarmcheck mission plan MISSION --json` (the exact planner): the events of least makespan, then
least total travel, to a marked state, each robot's tasks and travel. from_state: plan from that
state of the supervisor (robots at their starts).)");
  m.def(
      "mission_run",
      [](const py::object& mission, const std::string& body, double dt, double max_time, double speed, uint64_t seed,
         const py::object& trace, bool records) {
        const std::string file = path_of(mission);
        const sm::Mission ms = sm::load_mission(file);
        if (body != "unicycle" && body != "kinematic")
          throw InputError("body", "expected one of unicycle|kinematic, got \"" + body + "\"");
        check_range(dt, 1e-4, 1.0, "dt", "a step in seconds in [0.0001, 1]");
        if (!(max_time > 0) || !std::isfinite(max_time) || max_time > 1e7)
          throw InputError("max_time", "expected a time in seconds in (0, 1e7]");
        check_range(speed, 1e-3, 100.0, "speed", "a speed in m/s in [0.001, 100]");
        sm::RunOptions o;
        if (body == "kinematic") o.body = sm::BodyModel::kinematic;
        o.dt_s = dt;
        o.max_time_s = max_time;
        o.speed_m_per_s = speed;
        o.seed = seed;
        std::unique_ptr<sm::TraceFile> trace_file;
        if (!trace.is_none()) trace_file = std::make_unique<sm::TraceFile>(path_of(trace), ms, o);
        const sm::RunResult r = without_gil([&](SignalPoll& poll) {
          MissionObserver observer(trace_file.get(), poll);
          return sm::run_mission(ms, o, &observer);
        });
        if (trace_file) trace_file->commit();   // interrupted: no trace (TraceFile removes its temporary)
        py::dict d = to_python(sm::mission_run_report(ms, r, file, body));
        if (records) d["event_records"] = to_python(json_io::to_json(r.events));
        return d;
      },
      py::arg("mission"), py::kw_only(), py::arg("body") = "unicycle", py::arg("dt") = 0.05,
      py::arg("max_time") = 3600.0, py::arg("speed") = 0.5, py::arg("seed") = 1, py::arg("trace") = py::none(),
      py::arg("records") = false,
      R"(`swarmcheck mission run MISSION --json`: the mission simulated under its supervisor, the same dict.
Keywords as the flags: body (unicycle | kinematic), dt, max_time, speed, seed; trace: a path for
the JSON Lines trace (written whole, or not at all when the run is interrupted). records=True adds
"event_records": every event as a dict (time_s, event, robot, controllable, state_after). Ctrl-C
raises KeyboardInterrupt.)");
}

}  // namespace swarmcheck::python
