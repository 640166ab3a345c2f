#include "impl/exploration/intocps_bodies.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "spec/util/demand.hpp"

namespace swarmcheck::impl::exploration {

namespace ex = swarmcheck::exploration;

IntocpsBodies::IntocpsBodies(const ex::IntocpsBodyModel& model, std::span<const ex::Point_m> starts)
    : model_(model), robots_(starts.size()) {
  initial_.reserve(starts.size());
  for (const ex::Point_m& p : starts) initial_.push_back(ex::intocps_body_initialised(0.0, p[0], p[1]));
  blocks_.resize((robots_ + kLanes - 1) / kLanes);
  for (std::size_t r = 0; r < blocks_.size() * kLanes; ++r)   // padding lanes copy the last robot
    put_lane(blocks_[r / kLanes], static_cast<int>(r % kLanes), initial_[std::min(r, robots_ - 1)]);
  solver_time_s_ = robots_ > 0 ? initial_.front().solver_time_s : 0.0;
}

ex::BodyState IntocpsBodies::pose(std::size_t r) const {
  SWARM_ASSERT(r < robots_);
  const std::array<double, 3> p = lane_pose(blocks_[r / kLanes], static_cast<int>(r % kLanes));
  return ex::BodyState{p[0], p[1], p[2]};
}

ex::IntocpsBodyState IntocpsBodies::state(std::size_t r) const {
  SWARM_ASSERT(r < robots_);
  if (!stepped_) return initial_[r];
  return get_lane(model_, blocks_[r / kLanes], static_cast<int>(r % kLanes), solver_time_s_);
}

std::vector<ex::IntocpsBodyState> IntocpsBodies::states() const {
  std::vector<ex::IntocpsBodyState> out;
  out.reserve(robots_);
  for (std::size_t r = 0; r < robots_; ++r) out.push_back(state(r));
  return out;
}

void IntocpsBodies::step_blocks(std::size_t begin, std::size_t end, std::span<const double> left,
                                std::span<const double> right, int32_t count) {
  for (std::size_t b = begin; b < end; ++b) {
    Lane l, r;
    for (int k = 0; k < kLanes; ++k) {
      const std::size_t robot = std::min(b * kLanes + static_cast<std::size_t>(k), robots_ - 1);
      l[k] = left[robot];
      r[k] = right[robot];
    }
    intocps_lanes_rk4(model_, blocks_[b], l, r, count);
  }
}

void IntocpsBodies::step(std::span<const double> left, std::span<const double> right, double t_s, double h_s,
                         tbb::task_arena& arena, bool parallel) {
  SWARM_DEMAND(left.size() == robots_ && right.size() == robots_);
  if (robots_ == 0) return;
  // Every clock is the same: fmi2DoStep's count of RK4 steps, once.
  const ex::IntocpsSolverSteps n = ex::intocps_solver_steps(solver_time_s_, t_s, h_s);
  if (n.count == 0) return;
  if (!parallel) {
    step_blocks(0, blocks_.size(), left, right, n.count);
  } else {
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks_.size(), 4),
                        [&](const tbb::blocked_range<std::size_t>& range) {
                          step_blocks(range.begin(), range.end(), left, right, n.count);
                        });
    });
  }
  solver_time_s_ = n.clock_after_s;
  stepped_ = true;
}

}  // namespace swarmcheck::impl::exploration
