#pragma once
// Every robot's intocps body (spec/exploration/body_intocps.hpp), stepped together. In a master
// step every robot runs the same number of RK4 steps (their solver clocks are equal: they start
// together and add the same h), so the count is computed once. Robots are held four to a block
// (intocps_lanes.hpp: one robot a lane, the spec's operations four at a time) and blocks run in
// parallel; each robot's bits are the model's.
#include <tbb/task_arena.h>

#include <cstdint>
#include <span>
#include <vector>

#include "impl/exploration/cache_line_allocator.hpp"
#include "impl/exploration/intocps_lanes.hpp"
#include "spec/exploration/body_intocps.hpp"
#include "spec/exploration/types.hpp"

namespace swarmcheck::impl::exploration {

class IntocpsBodies {
 public:
  IntocpsBodies() : model_(swarmcheck::exploration::IntocpsBodyModel{}) {}
  IntocpsBodies(const swarmcheck::exploration::IntocpsBodyModel& model,
                std::span<const swarmcheck::exploration::Point_m> starts);

  std::size_t size() const { return robots_; }
  // Robot r's outputs as its controller reads them (robot_x, robot_y, robot_theta).
  swarmcheck::exploration::BodyState pose(std::size_t r) const;
  // Robot r's whole memory, as the spec holds it.
  swarmcheck::exploration::IntocpsBodyState state(std::size_t r) const;
  std::vector<swarmcheck::exploration::IntocpsBodyState> states() const;

  // Every body over [t_s, t_s + h_s], robot r with servos (left[r], right[r]); on `arena` when
  // `parallel` (the caller decides from the robots and its threads).
  void step(std::span<const double> left, std::span<const double> right, double t_s, double h_s,
            tbb::task_arena& arena, bool parallel);

 private:
  void step_blocks(std::size_t begin, std::size_t end, std::span<const double> left, std::span<const double> right,
                   int32_t count);

  IntocpsLaneModel model_;
  std::size_t robots_ = 0;
  std::vector<IntocpsLanes, CacheLineAllocator<IntocpsLanes>> blocks_;   // the last one padded with copies
  std::vector<swarmcheck::exploration::IntocpsBodyState> initial_;       // until the first step (its outputs were
                                                                         // formed with the default parameters)
  double solver_time_s_ = 0.0;
  bool stepped_ = false;
};

}  // namespace swarmcheck::impl::exploration
