#pragma once
// The intocps body (spec/exploration/body_intocps.hpp) for four robots at once: every quantity of
// the spec's rate and output evaluations F and G and of its RK4 step is a vector of four doubles,
// one robot a lane, so the divisions and products run four at a time (GCC vector extensions:
// two SSE2 instructions each on any x86-64, one AVX2 instruction where the CPU has it). Each lane
// performs exactly the spec's operations in the spec's order (IEEE arithmetic is exact per lane;
// -ffp-contract=off keeps products and sums apart), and the branches are per-lane selects, so each
// robot's bits are the model's. Only sin and cos (glibc's, as the spec calls them) and the
// encoders' trunc run lane by lane.
//
// Two savings keep the bits: G's rotation is the last F's (the spec recomputes cos and sin of the
// same theta), and the outputs are formed once, after a communication step's last G (they are
// functions of the state at that moment, which nothing changes before the next step).
#include <array>
#include <cstdint>

#include "spec/exploration/body_intocps.hpp"

namespace swarmcheck::impl::exploration {

inline constexpr int kLanes = 4;
using Lane = double __attribute__((vector_size(kLanes * sizeof(double))));
using LaneMask = long long __attribute__((vector_size(kLanes * sizeof(double))));

// Four robots' memory, lane k being robot 4b + k of block b.
struct alignas(64) IntocpsLanes {
  Lane s[swarmcheck::exploration::kIntocpsStates];       // states
  Lane rate[swarmcheck::exploration::kIntocpsStates];    // of the last F
  Lane contact[4];                                       // W: c_L (x, y), c_R (x, y), of the last G
  Lane position[2];                                      // POS, of the last G
  Lane reported[2];                                      // D, as the last F copied it
  Lane theta;                                            // Theta, of the last F
  Lane cos_theta, sin_theta;                             // its rotation (G reuses it)
  Lane remaining, controller_energy_seen, sensor_energy_seen;
  Lane origin[2];                                        // x0, y0
};

// The model's constants, broadcast to every lane.
struct IntocpsLaneModel {
  explicit IntocpsLaneModel(const swarmcheck::exploration::IntocpsBodyModel& m);
  swarmcheck::exploration::IntocpsBodyModel model;
};

// Lane k of `block` <- robot state `s`, and back (the outputs formed as G forms them).
void put_lane(IntocpsLanes& block, int k, const swarmcheck::exploration::IntocpsBodyState& s);
swarmcheck::exploration::IntocpsBodyState get_lane(const IntocpsLaneModel& m, const IntocpsLanes& block, int k,
                                                   double solver_time_s);
// The pose a lane's outputs give its controller (robot_x, robot_y, robot_theta).
std::array<double, 3> lane_pose(const IntocpsLanes& block, int k);

// `count` RK4 steps of the four robots with servos (left[k], right[k]) held.
void intocps_lanes_rk4(const IntocpsLaneModel& m, IntocpsLanes& block, const Lane& left, const Lane& right,
                       int32_t count);

}  // namespace swarmcheck::impl::exploration
