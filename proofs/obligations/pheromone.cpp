// Obligation pheromone-bounds: 0 <= tau <= R (max_ph + epsilon / a2) / (1 - f) is an inductive
// invariant of one cell's pheromone, over the reals, for R = 1..kMaxRobots covering robots.
#include <fmt/format.h>

#include "proofs/obligations/obligation.hpp"

namespace swarmcheck::proofs {
namespace {

constexpr int kMaxRobots = 8;

struct Cell {
  z3::expr f, c, max_ph, q, bound;   // q = epsilon / a2; bound = R (max_ph + q) / (1 - f)
};

// The parameters' domains (SPEC.md section 1) and the bound, division-free for nlsat.
Cell declare_cell(z3::context& ctx, z3::solver& s, int robots) {
  Cell k{ctx.real_const("f"), ctx.real_const("ertu_dt"), ctx.real_const("max_ph"),
         ctx.real_const("eps_over_a2"), ctx.real_const("bound")};
  const z3::expr eps = ctx.real_const("epsilon"), a2 = ctx.real_const("a2");
  s.add(k.c >= 0 && k.max_ph >= 0 && eps >= 0 && a2 > 0 && k.q * a2 == eps);
  // f = max(0, 1 - ertu dt), restricted to f < 1 (ertu dt > 0): the bound needs decay.
  s.add(k.f == z3::ite(1 - k.c < 0, ctx.real_val(0), 1 - k.c) && k.f < 1);
  s.add(k.bound * (1 - k.f) == ctx.real_val(robots) * (k.max_ph + k.q));
  return k;
}

// The deposits of `robots` robots on this cell in one step: each robot whose window covers the
// cell adds max_ph exp(-d / a1) + epsilon / a2 with exp(-d / a1) in (0, 1] (d >= 0, a1 > 0).
z3::expr deposits(z3::context& ctx, z3::solver& s, const Cell& k, int robots, const char* tag) {
  z3::expr sum = ctx.real_val(0);
  for (int r = 0; r < robots; ++r) {
    const z3::expr e = ctx.real_const(fmt::format("exp_{}_{}", tag, r).c_str());
    const z3::expr covers = ctx.bool_const(fmt::format("covers_{}_{}", tag, r).c_str());
    s.add(e > 0 && e <= 1);
    sum = sum + z3::ite(covers, k.max_ph * e + k.q, ctx.real_val(0));
  }
  return sum;
}

z3::expr invariant(const z3::expr& tau, const Cell& k) { return tau >= 0 && tau <= k.bound; }

enum class Query { init, step_decay, step_thesis };

z3::check_result check(Session& session, Query which, int robots) {
  z3::context& ctx = session.ctx();
  z3::solver s = session.make_nonlinear_solver();
  const Cell k = declare_cell(ctx, s, robots);
  const z3::expr tau = ctx.real_const("tau"), next = ctx.real_const("tau_next");
  const char* label = "init";
  if (which == Query::init) {
    // setEnvironment: every cell starts at 0, then each robot deposits once around its cell.
    s.add(next == deposits(ctx, s, k, robots, "init"));
  } else {
    s.add(invariant(tau, k));
    const z3::expr planning = ctx.bool_const("planning");
    const z3::expr dep = z3::ite(planning, deposits(ctx, s, k, robots, "step"), ctx.real_val(0));
    if (which == Query::step_decay) {
      // Decay function: one step multiplies by f (F(k) = f^k over the reals).
      s.add(next == k.f * tau + dep);
      label = "step-decay";
    } else {
      // The thesis's literal update: ph -= c ph; if (ph < 0) ph = 0.
      const z3::expr ev = tau - k.c * tau;
      s.add(next == z3::ite(ev < 0, ctx.real_val(0), ev) + dep);
      label = "step-thesis";
    }
  }
  s.add(!invariant(next, k));
  return session.check(s, fmt::format("{}-r{}", label, robots));
}

Outcome run(Session& session) {
  for (int robots = 1; robots <= kMaxRobots; ++robots)
    for (Query q : {Query::init, Query::step_decay, Query::step_thesis}) {
      const z3::check_result r = check(session, q, robots);
      if (r == z3::sat)
        return {Verdict::refuted,
                fmt::format("sat: query {} has a counterexample", session.queries().back().label),
                {}};
      if (r != z3::unsat)
        return {Verdict::unknown,
                fmt::format("unknown on query {}", session.queries().back().label), {}};
    }
  return {Verdict::proved,
          fmt::format("unsat: initiation and consecution (decay function and the thesis's update) "
                      "for R = 1..{}, {} queries",
                      kMaxRobots, session.queries().size()),
          {}};
}

}  // namespace

std::vector<Obligation> pheromone_obligations() {
  return {Obligation{
      "pheromone-bounds",
      "Every cell's pheromone stays within 0 <= tau <= R (max_ph + epsilon / a2) / (1 - f) when "
      "0 <= f < 1, R the number of robots whose deposit windows cover the cell.",
      Verdict::proved,
      {"real arithmetic, not doubles: rounding of the decay products and sums is not modelled",
       "one cell: evaporation tau' = f tau (decay function, F(k) = f^k over the reals) or the "
       "thesis's max(0, tau - ertu dt tau), then the deposits of a planning step",
       "exp(-d / a1) is abstracted to a value in (0, 1] (d >= 0, a1 > 0)",
       "R = 1..8 robots, each depositing at most once per planning step; parameters symbolic in "
       "their SPEC.md domains with ertu dt > 0 (f < 1)"},
      run}};
}

}  // namespace swarmcheck::proofs
