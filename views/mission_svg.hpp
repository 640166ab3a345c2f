#pragma once
// The picture of a mission (mission run --svg): regions (named rectangles), tasks (named
// diamonds), each robot's path from its start (hollow circle) to where it ended (filled), and a
// world's walls (its grid's border and occupied cells, dark grey) when the mission has one.
#include <string>
#include <vector>

#include "spec/mission/run.hpp"
#include "spec/mission/mission.hpp"

namespace swarmcheck::views {

struct MissionPicture {
  const swarmcheck::mission::Mission* mission = nullptr;
  std::vector<std::vector<swarmcheck::mission::Point>> paths;   // per robot
  std::string title;
  std::string subtitle;
};

std::string mission_svg(const MissionPicture& p);

// Collects the robots' paths for the picture and passes everything on to `next` (the trace
// writer, or nothing).
class MissionPathRecorder : public swarmcheck::mission::RunObserver {
 public:
  MissionPathRecorder(std::size_t robots, swarmcheck::mission::RunObserver* next);
  void on_event(const swarmcheck::mission::EventRecord& e) override;
  void on_step(const swarmcheck::mission::StepRecord& s) override;
  void on_interval(const swarmcheck::mission::IntervalRecord& i) override;
  const std::vector<std::vector<swarmcheck::mission::Point>>& paths() const { return paths_; }

 private:
  swarmcheck::mission::RunObserver* next_;
  std::vector<std::vector<swarmcheck::mission::Point>> paths_;
};

}  // namespace swarmcheck::views
