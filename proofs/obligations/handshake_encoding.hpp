#pragma once
// The handshake of handshake_concrete.hpp as a Z3 transition system, for k-induction. A step is
// spec's master_step itself (its order of reading the controllers and stepping them: Jacobi or
// Gauss-Seidel), run on a system of the spec's rules interpreted symbolically
// (handshake_system.hpp): the whole controller_rule with each robot's pose, heading and waypoint
// free reals and the tolerances free parameters, the Environment's handshake_stage_rule over
// all_arrived_rule, or the epoch rules. Robot motion is abstracted: each robot's pose is free in
// every step, and the Environment issues a free waypoint when it plans. The ghosts and the
// properties are stated here, over the pose (handshake_concrete.hpp).
#include <map>
#include <memory>
#include <vector>

#include "proofs/obligations/handshake_concrete.hpp"
#include "proofs/obligations/kinduction.hpp"
#include "proofs/obligations/translate.hpp"

namespace swarmcheck::proofs::handshake {

struct Frame {   // the state at the start of a step
  z3::expr flag, eout, epoch;
  std::vector<z3::expr> out, driving, ack, done;        // controllers, as computed
  std::vector<z3::expr> port_out, port_ack, port_done;  // as the Environment reads them
  std::vector<z3::expr> wx, wy;                         // each robot's current waypoint
  std::vector<z3::expr> reached, fresh;                 // ghosts
};

struct Step {    // what happens in a step
  std::vector<z3::expr> x, y, theta, new_wx, new_wy;    // inputs
  std::vector<z3::expr> at;                             // robot at its waypoint (the property's)
  z3::expr plan;
  std::vector<z3::expr> accept;
  z3::expr early_plan;             // violates no-early-plan
  z3::expr stale_accept;           // violates fresh-acceptance
};

class Encoding : public TransitionSystem {
 public:
  // strengthen: conjoin the variant's auxiliary invariant (lemma) to the property, so that
  // k-induction closes at k = 0 or 1 instead of k ~ 2 robots; the lemma is proved with it.
  // With a session, the spec functions it translates are the obligation's reads.
  Encoding(z3::context& ctx, Variant v, int robots, bool strengthen, Session* session = nullptr);
  z3::expr init(int frame) override;
  z3::expr trans(int step) override;
  z3::expr good(int step) override;   // the two properties (and the lemma, if strengthened)
  z3::expr property(int step);        // the two properties only
  z3::expr lemma(int frame);
  z3::expr differ(int frame_a, int frame_b) override;

  const Frame& frame(int t);
  const Step& step(int t);
  int robots() const { return n_; }
  const Variant& variant() const { return v_; }
  // The controller parameters the encoding leaves free (tolerance, orientation tolerances).
  z3::expr tolerance() const { return tol_; }
  z3::expr orient_tolerance() const { return otol_; }
  z3::expr reorient() const { return reo_; }

 private:
  Frame make_frame(int t);
  Step make_step(int t);

  z3::context& ctx_;
  Variant v_;
  int n_;
  bool strengthen_;
  Translator tr_;
  z3::expr tol_, otol_, reo_;
  std::map<int, Frame> frames_;
  std::map<int, Step> steps_;
  std::map<int, z3::expr> next_;   // frame t+1's equations, built with step t
};

}  // namespace swarmcheck::proofs::handshake
