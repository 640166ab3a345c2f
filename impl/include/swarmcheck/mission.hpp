#pragma once
// swarmcheck: missions under a supervisor (system B, part 2). Link swarmcheck::swarmcheck (or
// swarmcheck::mission alone).
//
//   #include <swarmcheck/mission.hpp>
//   namespace sm = swarmcheck::mission;
//   const sm::Mission m = sm::load_mission("thesis-mission.json");  // checked; throws swarmcheck::InputError
//   sm::Planner planner(m);
//   const sm::Plan p = planner.plan(sm::initial_query(m));          // least makespan, then total
//   sm::RunOptions o;
//   o.body = sm::BodyModel::kinematic;
//   sm::TraceFile trace("mission.jsonl", m, o);                      // optional: JSON Lines
//   const sm::RunResult r = sm::run_mission(m, o, &trace);
//   trace.commit();                                                  // the file appears whole
//   std::printf("%s at t=%.2f s\n", r.reason.c_str(), r.time_s);
//
// The mission file, the planning cost model and the rules of a run are swarmcheck's spec
// (spec/mission/mission.hpp, plan.hpp, run.hpp); the runner here follows them exactly as the
// reference model does, record for record (swarmcheck's conformance harness checks it).
#include <memory>
#include <string>

#include "spec/mission/mission.hpp"
#include "spec/mission/plan.hpp"
#include "spec/mission/run.hpp"
#include "spec/util/input_error.hpp"

namespace swarmcheck::mission {

// Reads the mission file and the .fsm it names (relative to the mission file's folder) and runs
// every check of check_mission.
Mission load_mission(const std::string& path);
// The files load_mission(path) reads: the mission file and the .fsm it names (for a command's
// check that none of its outputs is one of its inputs). Throws InputError as load_mission does
// when the mission file cannot be read or parsed.
std::vector<std::string> mission_input_files(const std::string& path);

// The exact planner: best-first Pareto label setting over (FSM state, each robot's position).
// It keeps its own copy of the mission, compiles the FSM once, and remembers plans per query.
class Planner {
 public:
  explicit Planner(const Mission& m);
  ~Planner();
  Planner(Planner&&) noexcept;
  Planner& operator=(Planner&&) noexcept;

  // Throws InputError when q.from is not a state of the FSM or the vectors have the wrong size.
  Plan plan(const PlanQuery& q);
  std::size_t cache_hits() const;
  std::size_t labels_last() const;  // labels the last search created

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Runs the mission in simulation (spec/mission/run.hpp); the observer sees every event and step.
RunResult run_mission(const Mission& m, const RunOptions& o = {}, RunObserver* observer = nullptr);

// The run as a JSON Lines trace (a header, then one record per event and per step, doubles that
// read back to the same bits) written to a temporary file beside `path`; commit() renames it onto
// `path`. Without commit() (an error, an exception) nothing is left behind.
class TraceFile final : public RunObserver {
 public:
  TraceFile(const std::string& path, const Mission& m, const RunOptions& o);
  ~TraceFile() override;
  void on_event(const EventRecord& e) override;
  void on_step(const StepRecord& s) override;
  void on_interval(const IntervalRecord& i) override;
  void commit();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace swarmcheck::mission
