#pragma once
// The servo commands as the spec computes them (servo_mix_rule, then saturate_servo_rule or
// thesis_clamp_rule, spec/exploration/controller.cpp), interpreted over IEEE doubles (FP
// theory, round to nearest even, no fused multiply-add: the build uses -ffp-contract=off).
#include "proofs/obligations/translate.hpp"
#include "spec/exploration/types.hpp"

namespace swarmcheck::proofs::servo {

enum class Clamp { spec, thesis };

struct Commands {
  z3::expr left, right;
};

// The two saturated servo commands for the linear and turn commands v and w (FP terms).
Commands commands(Translator& t, const exploration::RobotParams& rp, const sym::Real& v, const sym::Real& w,
                  Clamp clamp);

}  // namespace swarmcheck::proofs::servo
