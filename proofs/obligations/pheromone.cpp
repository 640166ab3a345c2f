// Obligation pheromone-bounds: every cell's pheromone stays within
//   0 <= tau <= R (max_ph + epsilon / a2) / min(1, ertu dt)
// (the bound stated over the parameters: 1 - min(1, ertu dt) is the decay a correct factor
// gives), for R = 1..kMaxRobots covering robots, when ertu dt > 0. The evaporation factor, the
// thesis's update and the deposit are the spec's rules (decay.hpp, deposit.hpp) interpreted over
// the reals; a counterexample is replayed through their concrete interpretation.
#include <cmath>
#include <fmt/format.h>

#include "proofs/obligations/obligation.hpp"
#include "proofs/obligations/translate.hpp"
#include "spec/exploration/decay.hpp"
#include "spec/exploration/deposit.hpp"

namespace swarmcheck::proofs {
namespace {

using S = num::Symbolic;
using C = num::Concrete;
constexpr int kMaxRobots = 8;

enum class Query { init, step_decay, step_thesis };

const char* label_of(Query q) {
  return q == Query::init ? "init" : q == Query::step_decay ? "step-decay" : "step-thesis";
}

// The symbolic world of one query: parameters, the cell's pheromone, each robot's deposit
// distance and coverage.
struct World {
  sym::Real ertu = sym::Real::var("ertu"), dt = sym::Real::var("step_size"), max_ph = sym::Real::var("max_ph"),
            epsilon = sym::Real::var("epsilon"), a1 = sym::Real::var("a1"), a2 = sym::Real::var("a2"),
            tau = sym::Real::var("tau");
  std::vector<sym::Real> distance;
  std::vector<sym::Bool> covers;
  sym::Bool planning = sym::Bool::var("planning");
};

// The next pheromone of the cell through the spec's rules, in domain D.
template <class D>
typename D::Real next_tau(Query q, const typename D::Real& ertu, const typename D::Real& dt,
                          const exploration::DepositParamsT<D>& dp, const typename D::Real& tau,
                          const std::vector<typename D::Real>& distance, const std::vector<typename D::Bool>& covers,
                          const typename D::Bool& planning) {
  typename D::Real dep(0.0);
  for (std::size_t r = 0; r < distance.size(); ++r)
    dep = dep + num::select(covers[r], exploration::deposit_amount_rule<D>(dp, distance[r]), typename D::Real(0.0));
  if (q == Query::init) return dep;   // every cell starts at 0; each robot deposits once
  const typename D::Real evaporated =
      q == Query::step_decay ? exploration::evaporation_factor_rule<D>(ertu, dt) * tau
                             : exploration::thesis_evaporate_rule<D>(tau, ertu * dt);
  return evaporated + num::select(planning, dep, typename D::Real(0.0));
}

struct Check {
  z3::check_result result;
  std::string detail;
};

Check check(Session& session, Query q, int robots) {
  z3::context& ctx = session.ctx();
  Translator t(ctx, RealTheory::real);
  World w;
  for (int r = 0; r < robots; ++r) {
    w.distance.push_back(sym::Real::var(fmt::format("distance_{}", r)));
    w.covers.push_back(sym::Bool::var(fmt::format("covers_{}", r)));
  }
  const z3::expr ertu = t(w.ertu), dt = t(w.dt), max_ph = t(w.max_ph), eps = t(w.epsilon), a1 = t(w.a1),
                 a2 = t(w.a2), tau = t(w.tau), bound = ctx.real_const("bound"), q_over = ctx.real_const("eps_over_a2");
  const z3::expr next = t(next_tau<S>(q, w.ertu, w.dt, {w.max_ph, w.a1, w.epsilon, w.a2}, w.tau, w.distance,
                                      w.covers, w.planning));
  auto base = [&](z3::solver& s) {
    // The parameters' domains (SPEC.md section 1), decay present (ertu dt > 0), distances >= 0.
    s.add(ertu >= 0 && dt > 0 && ertu * dt > 0 && max_ph >= 0 && eps >= 0 && a1 > 0 && a2 > 0);
    for (const sym::Real& d : w.distance) s.add(t(d) >= 0);
    s.add(q_over * a2 == eps);
    const z3::expr c = ertu * dt;
    // bound * min(1, ertu dt) = R (max_ph + epsilon / a2), division-free for nlsat.
    s.add(bound * z3::ite(c < 1, c, ctx.real_val(1)) == ctx.real_val(robots) * (max_ph + q_over));
    if (q != Query::init) s.add(tau >= 0 && tau <= bound);
    s.add(t.side_conditions());
  };
  // The default solver (its nonlinear core) answers these in well under a second where the
  // qfnra-nlsat tactic takes seconds at 8 robots.
  z3::solver s = session.make_nonlinear_solver();
  base(s);
  s.add(!(next >= 0 && next <= bound));
  const std::string label = fmt::format("{}-r{}", label_of(q), robots);
  const z3::check_result r = session.check(s, label);
  if (r != z3::sat) return {r, ""};
  // A counterexample: ask for one that leaves the bound by a margin, so that the doubles nearest
  // its values still leave it (not logged: the verdict is the query above).
  z3::solver wide = session.make_nonlinear_solver();
  base(wide);
  wide.add(next < 0 || next > bound * ctx.real_val(1001, 1000) + ctx.real_val(1, 1000));
  const bool robust = wide.check() == z3::sat;
  const z3::model m = robust ? wide.get_model() : s.get_model();
  auto d = [&](const sym::Real& x) { return model_double(m, t(x)); };
  auto b = [&](const sym::Bool& x) { return m.eval(t(x), true).is_true(); };
  std::vector<double> dist;
  std::vector<bool> cov;
  for (int k = 0; k < robots; ++k) {
    dist.push_back(d(w.distance[static_cast<std::size_t>(k)]));
    cov.push_back(b(w.covers[static_cast<std::size_t>(k)]));
  }
  // Replay through the executed code (the concrete interpretation of the same rules), and the
  // bound in doubles.
  const double e = d(w.ertu), st = d(w.dt), mp = d(w.max_ph), ep = d(w.epsilon), x1 = d(w.a1), x2 = d(w.a2);
  const double tv = d(w.tau);
  const double got = next_tau<C>(q, e, st, {mp, x1, ep, x2}, tv, dist, cov, b(w.planning));
  const double bd = robots * (mp + ep / x2) / std::min(1.0, e * st);
  const bool confirmed = (q == Query::init || (tv >= 0 && tv <= bd)) && !(got >= 0 && got <= bd);
  return {confirmed ? z3::sat : z3::unknown,
          fmt::format("{}: ertu = {:.6g}, step_size = {:.6g}, max_ph = {:.6g}, epsilon = {:.6g}, a1 = {:.6g}, "
                      "a2 = {:.6g}, tau = {:.6g}: the next pheromone is {:.6g} against the bound {:.6g} ({})",
                      label, e, st, mp, ep, x1, x2, tv, got, bd,
                      confirmed ? "confirmed by running evaporation_factor_rule, thesis_evaporate_rule and "
                                  "deposit_amount_rule"
                                : "NOT reproduced by the executed code: a spurious counterexample")};
}

Outcome run_pheromone(Session& session) {
  for (int robots = 1; robots <= kMaxRobots; ++robots)
    for (Query q : {Query::init, Query::step_decay, Query::step_thesis}) {
      const Check c = check(session, q, robots);
      if (c.result == z3::sat) return {Verdict::refuted, "sat: " + c.detail, {}};
      if (c.result != z3::unsat)
        return {Verdict::unknown,
                c.detail.empty() ? fmt::format("unknown on query {}", session.queries().back().label) : c.detail,
                {}};
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
      "Every cell's pheromone stays within 0 <= tau <= R (max_ph + epsilon / a2) / min(1, ertu dt) "
      "whenever ertu dt > 0, R the number of robots whose deposit windows cover the cell.",
      Verdict::proved,
      {"the evaporation factor, the thesis's update and the deposit are the spec's rules "
       "(evaporation_factor_rule, thesis_evaporate_rule, deposit_amount_rule) interpreted over the "
       "reals: rounding is not modelled; a counterexample counts only when the doubles nearest its "
       "values reproduce it through the executed code",
       "one cell: evaporation tau' = f tau (decay function, F(k) = f^k over the reals) or the "
       "thesis's update, then the deposits of a planning step",
       "exp is uninterpreted: positive, at most 1 for a non-positive argument; deposit distances "
       "are free reals >= 0",
       "R = 1..8 robots, each depositing at most once per planning step; parameters free in their "
       "SPEC.md domains with ertu dt > 0"},
      run_pheromone,
      {"exploration::evaporation_factor_rule", "exploration::thesis_evaporate_rule",
       "exploration::deposit_amount_rule"}}};
}

}  // namespace swarmcheck::proofs
