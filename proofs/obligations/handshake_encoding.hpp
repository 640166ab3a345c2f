#pragma once
// The handshake of handshake_concrete.hpp as a Z3 transition system over booleans (and 2-bit
// epochs), for k-induction. Robot motion is abstracted: arrival is a free boolean input per
// robot and step. The flag protocol's two sides are tabulated from the spec's own functions:
// environment_handshake over (flag, onDestinationOutput, all_arrived) and controller_step's
// onDestinationOutput over (output, input, robot on its waypoint).
#include <map>
#include <vector>

#include "proofs/obligations/handshake_concrete.hpp"
#include "proofs/obligations/kinduction.hpp"

namespace swarmcheck::proofs::handshake {

struct Frame {   // the state at the start of a step
  z3::expr flag, eout, epoch;
  std::vector<z3::expr> out, ack, done;                 // controllers, as computed
  std::vector<z3::expr> port_out, port_ack, port_done;  // as the Environment reads them
  std::vector<z3::expr> reached, fresh;                 // ghosts
};

struct Step {    // what happens in a step
  std::vector<z3::expr> arrival;   // inputs
  z3::expr plan;
  std::vector<z3::expr> accept, arrive;
  z3::expr early_plan;             // violates no-early-plan
  z3::expr stale_accept;           // violates fresh-acceptance
};

class Encoding : public TransitionSystem {
 public:
  // strengthen: conjoin the variant's auxiliary invariant (lemma) to the property, so that
  // k-induction closes at k = 0 instead of k ~ 2 robots; the lemma is proved with it.
  Encoding(z3::context& ctx, Variant v, int robots, bool strengthen);
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

 private:
  Frame make_frame(int t);
  Step make_step(int t);
  z3::expr next_state(int t);   // frame t + 1 as a function of frame t and step t

  z3::context& ctx_;
  Variant v_;
  int n_;
  bool strengthen_;
  std::map<int, Frame> frames_;
  std::map<int, Step> steps_;
  std::map<int, z3::expr> next_;   // frame t+1's equations, built with step t
};

}  // namespace swarmcheck::proofs::handshake
