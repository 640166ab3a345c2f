#pragma once
// The servo mix and saturation of SPEC.md section 8 step 6 over IEEE doubles (FP theory,
// fpa_sort<64>, round to nearest even, no fused multiply-add: the build uses -ffp-contract=off).
// Exposed so that the tests can check the encoding against spec/exploration/controller.cpp.
#include "proofs/obligations/z3.hpp"
#include "spec/exploration/types.hpp"

namespace swarmcheck::proofs::servo {

// saturate_servo: NaN -> 0, > 1 -> 1, < -1 -> -1, else the value.
z3::expr saturate(const z3::expr& u);
// thesis_clamp: if (u > 1) u = 1; else if (u < -1) u = -1;
z3::expr thesis_clamp(const z3::expr& u);

struct Mix {
  z3::expr left, right;
};
// servo_left = (1/r) v + (L/(2r)) w, servo_right = -((1/r) v - (L/(2r)) w), before saturation;
// the constants 1/r and L/(2r) are the doubles the spec computes.
Mix mix(const exploration::RobotParams& rp, const z3::expr& v, const z3::expr& w);

}  // namespace swarmcheck::proofs::servo
