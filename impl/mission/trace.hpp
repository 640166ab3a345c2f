#pragma once
// The mission trace, JSON Lines: a header, then, in the order they happen, one record per
// event and one per simulation step (after time 0's events, then after every step).
//   {"type":"header","format":"swarmcheck-mission-trace","version":1,"mission":..,"fsm":..,
//    "initial_state":..,"robots":[names],"body":"unicycle"|"kinematic","dt":..}
//   {"type":"event","t":..,"event":"a3s","robot":"A","kind":"c"|"uc","state":<state after>}
//   {"type":"step","t":..,"state":..,"positions":[[x,y],..],"blocked":[false,..],
//    "yielded":[false,..]}                          (yielded: kept its pose for another robot)
//   {"type":"interval","robot":"A","activity":"busy"|"waiting for the supervisor"|
//    "waiting for a task"|"waiting for a robot","from":..,"to":..}      (as each robot's activity interval closes)
// Doubles are written so that they read back to the same bits. The public TraceFile
// (swarmcheck/mission.hpp) is a TraceWriter on an io::AtomicFile.
#include <iosfwd>
#include <string>
#include <vector>

#include "spec/mission/run.hpp"

namespace swarmcheck::impl::mission {

using swarmcheck::mission::EventRecord;
using swarmcheck::mission::RunObserver;
using swarmcheck::mission::RunOptions;
using swarmcheck::mission::StepRecord;

class TraceWriter : public RunObserver {
 public:
  TraceWriter(std::ostream& out, const swarmcheck::mission::Mission& m, const RunOptions& o);
  void on_event(const EventRecord& e) override;
  void on_step(const StepRecord& s) override;
  void on_interval(const swarmcheck::mission::IntervalRecord& i) override;

 private:
  std::ostream& out_;
};

struct TraceEntry {
  std::size_t line = 0;   // in the file, from 1
  bool is_event = false;
  EventRecord event{};  // when is_event; {}: the bool is false, not indeterminate (UBSan)
  StepRecord step{};    // otherwise
};

struct MissionTrace {
  std::string initial_state;
  std::vector<std::string> robots;
  std::vector<TraceEntry> entries;
  std::vector<swarmcheck::mission::IntervalRecord> intervals;  // in file order
};

// Reads a trace; a malformed line is an InputError at "source:line". Beyond each record's
// fields (no field it does not know): the header comes first; times are finite and >= 0; events
// and steps are in time order (never earlier than the record before; a step strictly after the
// last step); an event names a robot of the header; an interval names one too, does not end
// before it starts, nor start before that robot's last interval ended.
MissionTrace read_trace(std::istream& in, const std::string& source);

// The trace is a run of the mission `m`: its robots, in order, and initial state; its events,
// each an event of the mission's FSM, of the robot its meaning names, controllable as the FSM
// says, and leading from the state before it to the state the record names (the supervisor's
// transition); and every step record's state the state the events so far have led to. An
// InputError at "source:line: field" otherwise.
void check_trace_against_mission(const MissionTrace& t, const swarmcheck::mission::Mission& m, const std::string& source);

}  // namespace swarmcheck::impl::mission
