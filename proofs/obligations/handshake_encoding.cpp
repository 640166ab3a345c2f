#include "proofs/obligations/handshake_encoding.hpp"

#include <fmt/format.h>

#include "proofs/obligations/handshake_system.hpp"

namespace swarmcheck::proofs::handshake {
namespace {

using S = num::Symbolic;

z3::expr all_of(z3::context& c, const std::vector<z3::expr>& v) {
  z3::expr r = c.bool_val(true);
  for (const z3::expr& e : v) r = r && e;
  return r;
}

z3::expr magnitude(const z3::expr& v) { return z3::ite(v < 0, -v, v); }

}  // namespace

Encoding::Encoding(z3::context& ctx, Variant v, int robots, bool strengthen, Session* session)
    : ctx_(ctx), v_(v), n_(robots), strengthen_(strengthen),
      tr_(session ? Translator(*session, RealTheory::real, false) : Translator(ctx, RealTheory::real, false)),
      tol_(tr_(sym::Real::var("tolerance"))), otol_(tr_(sym::Real::var("orient_tolerance"))),
      reo_(tr_(sym::Real::var("reorient"))) {}

Frame Encoding::make_frame(int t) {
  auto b = [&](const std::string& name) { return ctx_.bool_const(fmt::format("{}@{}", name, t).c_str()); };
  auto e = [&](const std::string& name) { return ctx_.int_const(fmt::format("{}@{}", name, t).c_str()); };
  auto r = [&](const std::string& name) { return ctx_.real_const(fmt::format("{}@{}", name, t).c_str()); };
  const bool flag = v_.protocol == Protocol::flag;
  Frame f{flag ? b("flag") : ctx_.bool_val(true), flag ? b("env_out") : ctx_.bool_val(false),
          flag ? ctx_.int_val(0) : e("epoch"), {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}};
  for (int i = 0; i < n_; ++i) {
    if (flag) {
      f.out.push_back(b(fmt::format("out_{}", i)));
      f.driving.push_back(b(fmt::format("driving_{}", i)));
      f.ack.push_back(ctx_.int_val(0));
      f.done.push_back(ctx_.bool_val(true));
    } else {
      f.out.push_back(ctx_.bool_val(true));
      f.driving.push_back(ctx_.bool_val(false));
      f.ack.push_back(e(fmt::format("ack_{}", i)));
      f.done.push_back(b(fmt::format("done_{}", i)));
    }
    if (v_.late_controller) {   // the port holds last step's output: a state variable
      f.port_out.push_back(flag ? b(fmt::format("port_out_{}", i)) : ctx_.bool_val(true));
      f.port_ack.push_back(flag ? ctx_.int_val(0) : e(fmt::format("port_ack_{}", i)));
      f.port_done.push_back(flag ? ctx_.bool_val(true) : b(fmt::format("port_done_{}", i)));
    } else {
      f.port_out.push_back(f.out.back());
      f.port_ack.push_back(f.ack.back());
      f.port_done.push_back(f.done.back());
    }
    f.wx.push_back(r(fmt::format("wx_{}", i)));
    f.wy.push_back(r(fmt::format("wy_{}", i)));
    f.reached.push_back(b(fmt::format("reached_{}", i)));
    f.fresh.push_back(b(fmt::format("fresh_{}", i)));
  }
  return f;
}

const Frame& Encoding::frame(int t) {
  auto it = frames_.find(t);
  if (it == frames_.end()) it = frames_.emplace(t, make_frame(t)).first;
  return it->second;
}

const Step& Encoding::step(int t) {
  auto it = steps_.find(t);
  if (it == steps_.end()) {
    Step s = make_step(t);
    it = steps_.emplace(t, std::move(s)).first;
  }
  return it->second;
}

// Builds step t and the equations of frame t + 1: spec's master_step, in the variant's order, on
// a system of the spec's rules whose state is frame t's (handshake_system.hpp).
Step Encoding::make_step(int t) {
  const Frame cur = frame(t);
  const Frame nxt = frame(t + 1);
  const bool flag = v_.protocol == Protocol::flag;
  auto sreal = [&](const std::string& name) { return sym::Real::var(fmt::format("{}@{}", name, t)); };
  auto sbool = [&](const std::string& name) { return sym::Bool::var(fmt::format("{}@{}", name, t)); };
  auto sint = [&](const std::string& name) { return sym::Int::var(fmt::format("{}@{}", name, t)); };
  Step s{{}, {}, {}, {}, {}, {}, ctx_.bool_val(false), {}, ctx_.bool_val(false), ctx_.bool_val(false)};
  z3::expr eq = ctx_.bool_val(true);
  // The controller parameters: the tolerances free, the rest the RobotParams defaults.
  exploration::ControllerParamsT<S> params = exploration::symbolic_controller_params(exploration::RobotParams{});
  params.tolerance_m = sym::Real::var("tolerance");
  params.orient_tolerance_rad = sym::Real::var("orient_tolerance");
  params.reorient_rad = sym::Real::var("reorient");
  // The robots in the step: free poses; the waypoints the frame's.
  std::vector<RobotView<S>> robots;
  for (int i = 0; i < n_; ++i) {
    const auto k = static_cast<std::size_t>(i);
    robots.push_back({sreal(fmt::format("x_{}", i)), sreal(fmt::format("y_{}", i)), sreal(fmt::format("theta_{}", i)),
                      sreal(fmt::format("wx_{}", i)), sreal(fmt::format("wy_{}", i))});
    s.x.push_back(tr_(robots.back().x));
    s.y.push_back(tr_(robots.back().y));
    s.theta.push_back(tr_(robots.back().theta));
    s.new_wx.push_back(ctx_.real_const(fmt::format("new_wx_{}@{}", i, t).c_str()));
    s.new_wy.push_back(ctx_.real_const(fmt::format("new_wy_{}@{}", i, t).c_str()));
    // The property's "at its waypoint", over the pose.
    s.at.push_back(magnitude(cur.wx[k] - s.x[k]) + magnitude(cur.wy[k] - s.y[k]) < tol_);
  }
  const exploration::MasterOrder order =
      v_.master == Master::jacobi ? exploration::MasterOrder::jacobi : exploration::MasterOrder::gauss_seidel;
  if (flag) {
    SymbolicFlagSystem sys;
    sys.params = params;
    sys.env = {sbool("flag"), sbool("env_out")};
    sys.robots = robots;
    sys.late = v_.late_controller;
    for (int i = 0; i < n_; ++i) {
      sys.internal.push_back({sbool(fmt::format("out_{}", i)), sbool(fmt::format("driving_{}", i)),
                              sreal(fmt::format("beta_{}", i)), sym::Real(0.0), sym::Real(0.0),
                              sreal(fmt::format("target_{}", i))});
      sys.port.push_back(v_.late_controller ? sbool(fmt::format("port_out_{}", i)) : sys.internal.back().idle);
    }
    exploration::master_step(exploration::Mode::cosim, sys, order);
    s.plan = tr_(sys.plan);
    eq = eq && nxt.flag == tr_(sys.env.flag) && nxt.eout == tr_(sys.env.output);
    for (int i = 0; i < n_; ++i) {
      const auto k = static_cast<std::size_t>(i);
      s.accept.push_back(tr_(sys.accept[k]));
      eq = eq && nxt.out[k] == tr_(sys.internal[k].idle) && nxt.driving[k] == tr_(sys.internal[k].driving);
      if (v_.late_controller) eq = eq && nxt.port_out[k] == tr_(sys.port[k]);
    }
  } else {
    SymbolicEpochSystem sys;
    sys.tolerance = params.tolerance_m;
    sys.epoch = sint("epoch");
    sys.robots = robots;
    sys.late = v_.late_controller;
    for (int i = 0; i < n_; ++i) {
      sys.internal.push_back({sint(fmt::format("ack_{}", i)), sbool(fmt::format("done_{}", i))});
      sys.port.push_back(v_.late_controller
                             ? exploration::EpochPortT<S>{sint(fmt::format("port_ack_{}", i)), sbool(fmt::format("port_done_{}", i))}
                             : exploration::EpochPortT<S>{sys.internal.back().ack, sys.internal.back().done});
    }
    exploration::master_step(exploration::Mode::cosim, sys, order);
    s.plan = tr_(sys.plan);
    eq = eq && nxt.epoch == tr_(sys.epoch);
    for (int i = 0; i < (v_.representative ? 1 : n_); ++i) {
      const auto k = static_cast<std::size_t>(i);
      s.accept.push_back(tr_(sys.accept[k]));
      eq = eq && nxt.ack[k] == tr_(sys.internal[k].ack) && nxt.done[k] == tr_(sys.internal[k].done);
      if (v_.late_controller)
        eq = eq && nxt.port_ack[k] == tr_(sys.port[k].ack) && nxt.port_done[k] == tr_(sys.port[k].done);
    }
  }
  // Waypoints: a plan issues free new ones.
  for (int i = 0; i < n_; ++i) {
    const auto k = static_cast<std::size_t>(i);
    eq = eq && nxt.wx[k] == z3::ite(s.plan, s.new_wx[k], cur.wx[k]) &&
         nxt.wy[k] == z3::ite(s.plan, s.new_wy[k], cur.wy[k]);
  }
  // Ghosts and the two properties (a representative proof: robot 0's; the others are free).
  std::vector<z3::expr> reached_now;
  for (int i = 0; i < (v_.representative ? 1 : n_); ++i) {
    const auto k = static_cast<std::size_t>(i);
    reached_now.push_back(cur.reached[k] || s.at[k]);
    s.stale_accept = s.stale_accept || (s.accept[k] && !cur.fresh[k]);
    eq = eq && nxt.reached[k] == (!s.plan && reached_now[k]) &&
         nxt.fresh[k] == (s.plan || (cur.fresh[k] && !s.accept[k]));
  }
  s.early_plan = s.plan && !all_of(ctx_, reached_now);
  eq = eq && tr_.take_new_facts();
  if (t == 0) eq = eq && tol_ > 0 && otol_ > 0 && reo_ > 0;
  next_.emplace(t, eq);
  return s;
}

z3::expr Encoding::init(int t) {
  const Frame& f = frame(t);
  const auto h = exploration::initial_handshake();
  const bool out0 = exploration::initial_controller().on_destination_output == 1;
  const bool driving0 = exploration::initial_controller().maneuver == 2;
  z3::expr r = ctx_.bool_val(true);
  if (v_.protocol == Protocol::flag)
    r = r && f.flag == ctx_.bool_val(h.flag == 1) && f.eout == ctx_.bool_val(h.on_destination_output == 1);
  else
    r = r && f.epoch == 0;
  for (std::size_t k = 0; k < f.out.size(); ++k) {
    r = r && f.ack[k] == 0 && f.done[k] && f.port_out[k] == f.out[k] && f.port_ack[k] == f.ack[k] &&
        f.port_done[k] == f.done[k] && f.reached[k] && !f.fresh[k];
    if (v_.protocol == Protocol::flag) r = r && f.out[k] == ctx_.bool_val(out0) && f.driving[k] == ctx_.bool_val(driving0);
  }
  return r;
}

z3::expr Encoding::trans(int t) {
  step(t);
  return next_.at(t);
}

z3::expr Encoding::property(int t) {
  const Step& s = step(t);
  return !s.early_plan && !s.stale_accept;
}

z3::expr Encoding::good(int t) {
  return strengthen_ ? property(t) && lemma(t) && lemma(t + 1) : property(t);
}

// The reachable states, as derived by hand from the protocol (SPEC.md section 7) and proved
// inductive together with the property. Flag protocol (prompt controllers, Jacobi): either the
// Environment has just planned (output 1, flag 0, every controller still idle, none has reached
// its new waypoint, each yet to accept) or it waits (output 0, flag 1, an idle controller's
// robot has reached its waypoint, none has an unaccepted waypoint). Epoch protocol: each
// controller has accepted the current epoch e (nothing fresh; arrived only once its robot has
// been at the waypoint) or the previous one e - 1 (arrived there, a fresh waypoint waiting); a
// port shows e or e - 1, e only once the controller has accepted e, and e - 1 only as arrived.
z3::expr Encoding::lemma(int t) {
  const Frame& f = frame(t);
  z3::expr r = ctx_.bool_val(true);
  if (v_.protocol == Protocol::flag) {
    z3::expr planned = !f.flag, waiting = f.flag;
    for (std::size_t k = 0; k < f.out.size(); ++k) {
      planned = planned && f.out[k] && !f.reached[k] && f.fresh[k];
      waiting = waiting && z3::implies(f.out[k], f.reached[k]) && !f.fresh[k];
    }
    return z3::implies(f.eout, planned) && z3::implies(!f.eout, waiting);
  }
  const z3::expr prev = z3::ite(f.epoch == 0, ctx_.int_val(exploration::kEpochs - 1), f.epoch - 1);
  r = r && f.epoch >= 0 && f.epoch < exploration::kEpochs;
  for (std::size_t k = 0; k < (v_.representative ? 1 : f.ack.size()); ++k) {
    r = r && (f.ack[k] == f.epoch || f.ack[k] == prev) &&
        z3::implies(f.ack[k] == prev, f.done[k] && f.fresh[k] && !f.reached[k]) &&
        z3::implies(f.ack[k] == f.epoch, !f.fresh[k] && z3::implies(f.done[k], f.reached[k])) &&
        (f.port_ack[k] == f.epoch || f.port_ack[k] == prev) &&
        z3::implies(f.port_ack[k] == f.epoch, f.ack[k] == f.epoch && z3::implies(f.port_done[k], f.done[k])) &&
        z3::implies(f.port_ack[k] == prev, f.port_done[k]);
  }
  return r;
}

z3::expr Encoding::differ(int a, int b) {
  const Frame& x = frame(a);
  const Frame& y = frame(b);
  z3::expr d = x.flag != y.flag || x.eout != y.eout || x.epoch != y.epoch;
  for (std::size_t k = 0; k < x.out.size(); ++k)
    d = d || x.out[k] != y.out[k] || x.driving[k] != y.driving[k] || x.ack[k] != y.ack[k] ||
        x.done[k] != y.done[k] || x.port_out[k] != y.port_out[k] || x.port_ack[k] != y.port_ack[k] ||
        x.port_done[k] != y.port_done[k] || x.wx[k] != y.wx[k] || x.wy[k] != y.wy[k] ||
        x.reached[k] != y.reached[k] || x.fresh[k] != y.fresh[k];
  return d;
}

}  // namespace swarmcheck::proofs::handshake
