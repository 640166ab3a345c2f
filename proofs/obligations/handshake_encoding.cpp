#include "proofs/obligations/handshake_encoding.hpp"

#include <fmt/format.h>

#include "spec/exploration/controller.hpp"
#include "spec/exploration/handshake.hpp"

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

Encoding::Encoding(z3::context& ctx, Variant v, int robots, bool strengthen)
    : ctx_(ctx), v_(v), n_(robots), strengthen_(strengthen), tr_(ctx, RealTheory::real, false),
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

// Builds step t and the equations of frame t + 1, from the spec's rules.
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
  // Controllers read the Environment's outputs of the previous step (both masters).
  std::vector<z3::expr> new_out, new_ack, new_done;
  for (int i = 0; i < n_; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const sym::Real x = sreal(fmt::format("x_{}", i)), y = sreal(fmt::format("y_{}", i)),
                    theta = sreal(fmt::format("theta_{}", i)), wx = sreal(fmt::format("wx_{}", i)),
                    wy = sreal(fmt::format("wy_{}", i));
    s.x.push_back(tr_(x));
    s.y.push_back(tr_(y));
    s.theta.push_back(tr_(theta));
    s.new_wx.push_back(ctx_.real_const(fmt::format("new_wx_{}@{}", i, t).c_str()));
    s.new_wy.push_back(ctx_.real_const(fmt::format("new_wy_{}@{}", i, t).c_str()));
    // The property's "at its waypoint", over the pose.
    s.at.push_back(magnitude(cur.wx[k] - s.x[k]) + magnitude(cur.wy[k] - s.y[k]) < tol_);
    if (flag) {
      const exploration::ControllerCoreT<S> before{sbool(fmt::format("out_{}", i)), sbool(fmt::format("driving_{}", i)),
                                                   sreal(fmt::format("beta_{}", i)), sym::Real(0.0), sym::Real(0.0),
                                                   sreal(fmt::format("target_{}", i))};
      const exploration::ControllerCoreT<S> after = exploration::controller_rule<S>(
          params, before, {x, y, theta, wx, wy, sbool("env_out"), sym::Real(kHandshakeStep_s)});
      const z3::expr o = tr_(after.idle), d = tr_(after.driving);
      new_out.push_back(o);
      new_ack.push_back(cur.ack[k]);
      new_done.push_back(cur.done[k]);
      s.accept.push_back(cur.out[k] && !o);
      eq = eq && nxt.out[k] == o && nxt.driving[k] == d;
    } else {
      const sym::Bool arrived = exploration::arrived_rule<S>({wx - x, wy - y}, params.tolerance_m);
      const exploration::EpochControllerT<S> after = exploration::epoch_controller_rule<S>(
          {sint(fmt::format("ack_{}", i)), sbool(fmt::format("done_{}", i))}, sint("epoch"), arrived);
      new_out.push_back(cur.out[k]);
      new_ack.push_back(tr_(after.ack));
      new_done.push_back(tr_(after.done));
      s.accept.push_back(cur.epoch != cur.ack[k]);
      eq = eq && nxt.ack[k] == new_ack[k] && nxt.done[k] == new_done[k];
    }
  }
  // Ports after the step: a late controller shows the output it had before the step.
  std::vector<z3::expr> port_out, port_ack, port_done;
  for (int i = 0; i < n_; ++i) {
    const auto k = static_cast<std::size_t>(i);
    port_out.push_back(v_.late_controller ? cur.out[k] : new_out[k]);
    port_ack.push_back(v_.late_controller ? cur.ack[k] : new_ack[k]);
    port_done.push_back(v_.late_controller ? cur.done[k] : new_done[k]);
    if (v_.late_controller)
      eq = eq && nxt.port_out[k] == port_out[k] && nxt.port_ack[k] == port_ack[k] &&
           nxt.port_done[k] == port_done[k];
  }
  // The Environment reads the ports of the previous step (Jacobi) or the new ones (G-S): the
  // ports are bound to symbolic names so the rules read them like any input.
  const bool gs = v_.master == Master::gauss_seidel;
  const auto& r_out = gs ? port_out : cur.port_out;
  const auto& r_ack = gs ? port_ack : cur.port_ack;
  const auto& r_done = gs ? port_done : cur.port_done;
  if (flag) {
    std::vector<sym::Bool> read;
    for (int i = 0; i < n_; ++i) {
      read.push_back(sbool(fmt::format("read_out_{}", i)));
      eq = eq && tr_(read.back()) == r_out[static_cast<std::size_t>(i)];
    }
    const sym::Bool all = exploration::all_arrived_rule<S>(read.size(), [&](std::size_t k) { return read[k]; });
    const exploration::HandshakeStepT<S> hs =
        exploration::environment_handshake_rule<S>({sbool("flag"), sbool("env_out")}, all);
    s.plan = tr_(hs.plan);
    eq = eq && nxt.flag == tr_(hs.next.flag) && nxt.eout == tr_(hs.next.output);
  } else {
    std::vector<sym::Int> acks;
    std::vector<sym::Bool> done;
    for (int i = 0; i < n_; ++i) {
      acks.push_back(sint(fmt::format("read_ack_{}", i)));
      done.push_back(sbool(fmt::format("read_done_{}", i)));
      eq = eq && tr_(acks.back()) == r_ack[static_cast<std::size_t>(i)] &&
           tr_(done.back()) == r_done[static_cast<std::size_t>(i)];
    }
    const exploration::EpochStepT<S> es = exploration::epoch_environment_rule<S>(sint("epoch"), acks, done);
    s.plan = tr_(es.plan);
    eq = eq && nxt.epoch == tr_(es.epoch);
  }
  // Waypoints: a plan issues free new ones.
  for (int i = 0; i < n_; ++i) {
    const auto k = static_cast<std::size_t>(i);
    eq = eq && nxt.wx[k] == z3::ite(s.plan, s.new_wx[k], cur.wx[k]) &&
         nxt.wy[k] == z3::ite(s.plan, s.new_wy[k], cur.wy[k]);
  }
  // Ghosts and the two properties.
  std::vector<z3::expr> reached_now;
  for (int i = 0; i < n_; ++i) {
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
  for (std::size_t k = 0; k < f.ack.size(); ++k) {
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
