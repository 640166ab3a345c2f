#include "proofs/obligations/handshake_encoding.hpp"

#include <fmt/format.h>

#include "spec/exploration/controller.hpp"
#include "spec/exploration/handshake.hpp"

namespace swarmcheck::proofs::handshake {
namespace {

constexpr unsigned kEpochBits = 2;   // kEpochs == 4

// A boolean function given by its truth table over 3 inputs, as a sum of minterms.
z3::expr from_table(z3::context& c, const bool (&table)[2][2][2], const z3::expr& a,
                    const z3::expr& b, const z3::expr& d) {
  z3::expr f = c.bool_val(false);
  for (int x = 0; x < 2; ++x)
    for (int y = 0; y < 2; ++y)
      for (int z = 0; z < 2; ++z)
        if (table[x][y][z]) f = f || ((x ? a : !a) && (y ? b : !b) && (z ? d : !d));
  return f.simplify();
}

struct EnvTables {
  bool plan[2][2][2], flag[2][2][2], eout[2][2][2];   // [flag][eout][all_arrived]
};

EnvTables env_tables() {
  EnvTables t{};
  for (int f = 0; f < 2; ++f)
    for (int o = 0; o < 2; ++o)
      for (int all = 0; all < 2; ++all) {
        const auto hs = exploration::environment_handshake(exploration::HandshakeState{f, o}, all == 1);
        t.plan[f][o][all] = hs.plan;
        t.flag[f][o][all] = hs.next.flag == 1;
        t.eout[f][o][all] = hs.next.on_destination_output == 1;
      }
  return t;
}

// controller_step's next onDestinationOutput, [output][input][robot on its waypoint].
struct ControllerTable {
  bool out[2][2][2];
};

ControllerTable controller_table() {
  ControllerTable t{};
  for (int o = 0; o < 2; ++o)
    for (int in = 0; in < 2; ++in)
      for (int at = 0; at < 2; ++at) {
        exploration::ControllerState c = exploration::initial_controller();
        c.on_destination_output = o;
        const exploration::BodyState pose{at ? 0.5 : 3.5, 0.5, 0.0};
        const auto n = exploration::controller_step(
            exploration::RobotParams{}, c, exploration::ControllerInputs{pose, {0.5, 0.5}, in});
        t.out[o][in][at] = n.on_destination_output == 1;
      }
  return t;
}

z3::expr all_of(z3::context& c, const std::vector<z3::expr>& v) {
  z3::expr r = c.bool_val(true);
  for (const z3::expr& e : v) r = r && e;
  return r;
}

}  // namespace

Encoding::Encoding(z3::context& ctx, Variant v, int robots, bool strengthen)
    : ctx_(ctx), v_(v), n_(robots), strengthen_(strengthen) {}

Frame Encoding::make_frame(int t) {
  auto b = [&](const std::string& name) { return ctx_.bool_const(fmt::format("{}@{}", name, t).c_str()); };
  auto e = [&](const std::string& name) {
    return ctx_.bv_const(fmt::format("{}@{}", name, t).c_str(), kEpochBits);
  };
  const bool flag = v_.protocol == Protocol::flag;
  Frame f{flag ? b("flag") : ctx_.bool_val(true), flag ? b("env_out") : ctx_.bool_val(false),
          flag ? ctx_.bv_val(0, kEpochBits) : e("epoch"), {}, {}, {}, {}, {}, {}, {}, {}};
  for (int i = 0; i < n_; ++i) {
    if (flag) {
      f.out.push_back(b(fmt::format("out_{}", i)));
      f.ack.push_back(ctx_.bv_val(0, kEpochBits));
      f.done.push_back(ctx_.bool_val(true));
    } else {
      f.out.push_back(ctx_.bool_val(true));
      f.ack.push_back(e(fmt::format("ack_{}", i)));
      f.done.push_back(b(fmt::format("done_{}", i)));
    }
    if (v_.late_controller) {   // the port holds last step's output: a state variable
      f.port_out.push_back(flag ? b(fmt::format("port_out_{}", i)) : ctx_.bool_val(true));
      f.port_ack.push_back(flag ? ctx_.bv_val(0, kEpochBits) : e(fmt::format("port_ack_{}", i)));
      f.port_done.push_back(flag ? ctx_.bool_val(true) : b(fmt::format("port_done_{}", i)));
    } else {
      f.port_out.push_back(f.out.back());
      f.port_ack.push_back(f.ack.back());
      f.port_done.push_back(f.done.back());
    }
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

// Builds step t and the equations of frame t + 1.
Step Encoding::make_step(int t) {
  static const EnvTables env = env_tables();
  static const ControllerTable ctl = controller_table();
  const Frame cur = frame(t);
  const Frame nxt = frame(t + 1);
  const bool flag = v_.protocol == Protocol::flag;
  Step s{{}, ctx_.bool_val(false), {}, {}, ctx_.bool_val(false), ctx_.bool_val(false)};
  z3::expr eq = ctx_.bool_val(true);
  // Controllers read the Environment's outputs of the previous step (both masters).
  std::vector<z3::expr> new_out, new_ack, new_done;
  for (int i = 0; i < n_; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const z3::expr arr = ctx_.bool_const(fmt::format("arrival_{}@{}", i, t).c_str());
    s.arrival.push_back(arr);
    if (flag) {
      const z3::expr o = from_table(ctx_, ctl.out, cur.out[k], cur.eout, arr);
      new_out.push_back(o);
      new_ack.push_back(cur.ack[k]);
      new_done.push_back(cur.done[k]);
      s.accept.push_back(cur.out[k] && !o);
      s.arrive.push_back(!cur.out[k] && o);
    } else {
      const z3::expr accept = cur.epoch != cur.ack[k];
      new_out.push_back(cur.out[k]);
      new_ack.push_back(z3::ite(accept, cur.epoch, cur.ack[k]));
      new_done.push_back(z3::ite(accept, ctx_.bool_val(false), cur.done[k] || arr));
      s.accept.push_back(accept);
      s.arrive.push_back(!accept && !cur.done[k] && arr);
    }
    if (flag) eq = eq && nxt.out[k] == new_out[k];
    else eq = eq && nxt.ack[k] == new_ack[k] && nxt.done[k] == new_done[k];
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
  // The Environment reads the ports of the previous step (Jacobi) or the new ones (G-S).
  const bool gs = v_.master == Master::gauss_seidel;
  const auto& r_out = gs ? port_out : cur.port_out;
  const auto& r_ack = gs ? port_ack : cur.port_ack;
  const auto& r_done = gs ? port_done : cur.port_done;
  if (flag) {
    const z3::expr all = all_of(ctx_, r_out);
    s.plan = from_table(ctx_, env.plan, cur.flag, cur.eout, all);
    eq = eq && nxt.flag == from_table(ctx_, env.flag, cur.flag, cur.eout, all) &&
         nxt.eout == from_table(ctx_, env.eout, cur.flag, cur.eout, all);
  } else {
    std::vector<z3::expr> ready;
    for (std::size_t k = 0; k < r_ack.size(); ++k) ready.push_back(r_ack[k] == cur.epoch && r_done[k]);
    s.plan = all_of(ctx_, ready);
    eq = eq && nxt.epoch == z3::ite(s.plan, cur.epoch + ctx_.bv_val(1, kEpochBits), cur.epoch);
  }
  // Ghosts and the two properties.
  std::vector<z3::expr> reached_now;
  for (int i = 0; i < n_; ++i) {
    const auto k = static_cast<std::size_t>(i);
    reached_now.push_back(cur.reached[k] || s.arrive[k]);
    s.stale_accept = s.stale_accept || (s.accept[k] && !cur.fresh[k]);
    eq = eq && nxt.reached[k] == (!s.plan && reached_now[k]) &&
         nxt.fresh[k] == (s.plan || (cur.fresh[k] && !s.accept[k]));
  }
  s.early_plan = s.plan && !all_of(ctx_, reached_now);
  next_.emplace(t, eq);
  return s;
}

z3::expr Encoding::init(int t) {
  const Frame& f = frame(t);
  const auto h = exploration::initial_handshake();
  const bool out0 = exploration::initial_controller().on_destination_output == 1;
  z3::expr r = ctx_.bool_val(true);
  if (v_.protocol == Protocol::flag)
    r = r && f.flag == ctx_.bool_val(h.flag == 1) && f.eout == ctx_.bool_val(h.on_destination_output == 1);
  else
    r = r && f.epoch == ctx_.bv_val(0, kEpochBits);
  for (std::size_t k = 0; k < f.out.size(); ++k) {
    r = r && f.out[k] == ctx_.bool_val(out0) && f.ack[k] == ctx_.bv_val(0, kEpochBits) && f.done[k] &&
        f.port_out[k] == f.out[k] && f.port_ack[k] == f.ack[k] && f.port_done[k] == f.done[k] &&
        f.reached[k] && !f.fresh[k];
  }
  return r.simplify();
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
// Environment has just planned (output 1, flag 0, every controller still idle, none on its new
// waypoint, each yet to accept) or it waits (output 0, flag 1, a controller is idle exactly
// when its robot is on its waypoint, none has an unaccepted waypoint). Epoch protocol: each
// controller has accepted the current epoch e (idle exactly when arrived, nothing fresh) or the
// previous one e - 1 (idle, arrived there, a fresh waypoint waiting); a port shows e or e - 1,
// e only once the controller has accepted e, and e - 1 only as arrived.
z3::expr Encoding::lemma(int t) {
  const Frame& f = frame(t);
  z3::expr r = ctx_.bool_val(true);
  if (v_.protocol == Protocol::flag) {
    z3::expr planned = !f.flag, waiting = f.flag;
    for (std::size_t k = 0; k < f.out.size(); ++k) {
      planned = planned && f.out[k] && !f.reached[k] && f.fresh[k];
      waiting = waiting && f.out[k] == f.reached[k] && !f.fresh[k];
    }
    return z3::implies(f.eout, planned) && z3::implies(!f.eout, waiting);
  }
  const z3::expr prev = f.epoch - ctx_.bv_val(1, kEpochBits);
  for (std::size_t k = 0; k < f.ack.size(); ++k) {
    r = r && (f.ack[k] == f.epoch || f.ack[k] == prev) &&
        z3::implies(f.ack[k] == prev, f.done[k] && f.fresh[k] && !f.reached[k]) &&
        z3::implies(f.ack[k] == f.epoch, !f.fresh[k] && f.done[k] == f.reached[k]) &&
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
    d = d || x.out[k] != y.out[k] || x.ack[k] != y.ack[k] || x.done[k] != y.done[k] ||
        x.port_out[k] != y.port_out[k] || x.port_ack[k] != y.port_ack[k] ||
        x.port_done[k] != y.port_done[k] || x.reached[k] != y.reached[k] || x.fresh[k] != y.fresh[k];
  return d.simplify();
}

}  // namespace swarmcheck::proofs::handshake
