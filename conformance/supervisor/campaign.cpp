#include "conformance/supervisor/campaign.hpp"

#include <rapidcheck.h>

#include <algorithm>
#include <cmath>

#include "conformance/supervisor/counterexample.hpp"
#include "conformance/supervisor/differential.hpp"
#include "conformance/supervisor/generators.hpp"
#include "impl/supervisor/fsm_io.hpp"
#include "impl/supervisor/operations.hpp"
#include "model/supervisor/operations.hpp"

namespace swarmcheck::conformance::supervisor {

namespace impl = swarmcheck::impl::supervisor;
namespace model = swarmcheck::model::supervisor;
using swarmcheck::supervisor::EventAttr;

namespace {

std::vector<Automaton> plant_parts(const std::vector<Automaton>& in) { return {in.begin(), in.end() - 1}; }

struct Case {
  std::string kind;
  std::vector<Automaton> inputs;   // for synthesis kinds: the plant's parts, then the spec
};

// 2..4 parts, each a ring of n_i states on its private event p<i>e0 (so every tuple of states is
// reachable by interleaving: the product has about n_1 ... n_k states, 10^3..10^5), with random
// edges on a second private event and on two shared events that synchronise the parts.
std::vector<Automaton> gen_big_parts() {
  // The size is drawn first: RapidCheck shrinks draws in order, so the first shrinks of a failing
  // big case make it small, and the many later candidates each cost a small model run.
  // Mostly 10^3..10^4.3 states; one case in eight up to 10^5 (the model takes seconds there).
  // chance() shrinks towards true, so `true` is always the smaller side here (the small range, no
  // edge), or shrinking would grow the case.
  const double top = *chance(88) ? 4.3 : 5.0;
  const double target = std::pow(10.0, 3.0 + *uniform(0, 101) / 100.0 * (top - 3.0));
  const int k = *uniform(2, 5);
  const int per_part = std::max(2, static_cast<int>(std::lround(std::pow(target, 1.0 / k))));
  const EventAttr s0{*chance(60), true}, s1{*chance(60), true};
  std::vector<Automaton> parts;
  for (int i = 0; i < k; ++i) {
    const std::string p = numbered("p", static_cast<std::size_t>(i));
    const int n = std::max(2, per_part + *uniform(-1, 2));
    Automaton a;
    for (int q = 0; q < n; ++q) a.states.push_back(numbered("q", static_cast<std::size_t>(q)));
    a.events = {{p + "e0", EventAttr{*chance(65), true}}, {p + "e1", EventAttr{*chance(65), true}}, {"s0", s0}, {"s1", s1}};
    for (int q = 0; q < n; ++q) {
      a.delta[a.states[q]][p + "e0"] = a.states[(q + 1) % n];
      for (const char* e : {"e1", "s0", "s1"}) {
        const std::string name = e[0] == 'e' ? p + e : std::string(e);
        if (!*chance(70)) a.delta[a.states[q]][name] = a.states[*uniform(0, n)];
      }
      if (*chance(35)) a.marked.insert(a.states[q]);
    }
    parts.push_back(a);
  }
  return parts;
}

Alphabet alphabet_of(const std::vector<Automaton>& parts) {
  Alphabet a;
  for (const auto& p : parts)
    for (const auto& [e, attr] : p.events) a[e] = attr;
  return a;
}

Case gen_case() {
  const std::string kind = *rc::gen::weightedElement<std::string>(
      {{3, "unary"}, {3, "product"}, {1, "big"}, {3, "synthesis"}, {1, "big_synth"}, {3, "inclusion"}, {1, "roundtrip"},
       {2, "control"}, {2, "observation"}});
  Case c{kind, {}};
  if (kind == "big" || kind == "big_synth") {
    c.inputs = gen_big_parts();
    if (kind == "big_synth") c.inputs.push_back(*gen_automaton(alphabet_of(c.inputs), {6, 90, 60}));
    return c;
  }
  const Alphabet alphabet = *gen_alphabet();
  if (kind == "unary") c.inputs = {*gen_automaton(alphabet, {300, 40, 20})};
  if (kind == "roundtrip") c.inputs = {*gen_automaton(alphabet, {100, 60, 30})};
  if (kind == "product") c.inputs = {*gen_automaton(alphabet, {40, 60, 30}), *gen_automaton(alphabet, {40, 60, 30})};
  if (kind == "synthesis") {
    // Marking from sparse to dense: with few marked states, coreachability decides which states
    // the supervisor keeps, and faults in the backward search show on small plants.
    const int marked_pct = *uniform(5, 71);
    c.inputs = {*gen_automaton(alphabet, {100, 70, marked_pct}), *gen_automaton(alphabet, {30, 95, 70})};
  }
  if (kind == "control") {
    // A random supervisor: mostly not controllable, sometimes blocking, so both witnesses run.
    c.inputs = {*gen_automaton(alphabet, {60, 70, 40}), *gen_automaton(alphabet, {30, 90, 60})};
  }
  if (kind == "observation")   // about half the events are unobservable (gen_alphabet)
    c.inputs = {*gen_automaton(alphabet, {40, 70, 40}), *gen_automaton(alphabet, {25, 95, 70})};
  if (kind == "inclusion") {
    const Automaton a = *gen_automaton(alphabet, {40, 40, 30});
    c.inputs = {a, *rc::gen::oneOf(gen_automaton(alphabet, {40, 40, 30}), rc::gen::just(model::trim(a)), rc::gen::just(a))};
  }
  return c;
}


void note(const Case& c, const BuiltSizes& built, Coverage& cov) {
  ++cov.cases_by_kind[c.kind];
  if (c.kind == "unary") cov.largest_unary_states = std::max(cov.largest_unary_states, c.inputs[0].states.size());
  cov.largest_product_states = std::max(cov.largest_product_states, built.product_states);
  if (c.kind == "synthesis" || c.kind == "big_synth" || c.kind == "observation") {
    cov.largest_plant_states = std::max(cov.largest_plant_states, built.product_states);
    cov.largest_supervisor_states = std::max(cov.largest_supervisor_states, built.supervisor_states);
    cov.empty_supervisors += built.supervisor_states == 0 ? 1 : 0;
  }
  if (c.kind == "inclusion" && !impl::language_inclusion(impl::compile(c.inputs[0]), impl::compile(c.inputs[1])).closed)
    ++cov.inclusions_failing;
}

// Without the states no input reaches, and without events no transition uses, when the
// difference stays: what is left is the part of the counterexample that matters.
std::vector<Automaton> reduce(const std::string& kind, std::vector<Automaton> in) {
  for (std::size_t i = 0; i < in.size(); ++i) {
    std::vector<Automaton> tried = in;
    tried[i] = model::accessible_part(tried[i]);
    if (tried[i] != in[i] && diff_case(kind, tried)) in = tried;
    for (const auto& [e, attr] : Alphabet(in[i].events)) {
      bool used = false;
      for (const auto& [q, row] : in[i].delta) used = used || row.count(e) > 0;
      if (used) continue;
      tried = in;
      tried[i].events.erase(e);
      if (diff_case(kind, tried)) in = tried;
    }
  }
  return in;
}

std::string command_for(const std::string& kind, const std::vector<std::string>& files) {
  std::string all;
  for (const auto& f : files) all += " " + f;
  if (kind == "unary") return "swarmcheck fsm check" + all + " --json [--engine model]";
  if (kind == "roundtrip") return "swarmcheck fsm export" + all + " --to fsm";
  if (kind == "inclusion") return "swarmcheck fsm compare" + all + " --json [--engine model]";
  if (kind == "product" || kind == "big") return "swarmcheck fsm product" + all + " -o product.fsm [--engine model]";
  std::string plants;
  for (std::size_t i = 0; i + 1 < files.size(); ++i) plants += " " + files[i];
  if (kind == "control") return "swarmcheck fsm controllable --plant" + plants + " --sup " + files.back() + " --json [--engine model]";
  if (kind == "observation")
    return "swarmcheck fsm project" + plants + " [--engine model]; swarmcheck fsm observable --plant" + plants + " --spec " +
           files.back() + " --json [--engine model]; swarmcheck fsm synth --plant" + plants + " --spec " + files.back() +
           " -o supervisor.fsm [--engine model]";
  return "swarmcheck fsm synth --plant" + plants + " --spec " + files.back() + " -o supervisor.fsm [--engine model]";
}

}  // namespace

std::optional<std::string> diff_case(const std::string& kind, const std::vector<Automaton>& in, BuiltSizes* built) {
  if (kind == "unary") return diff_unary(in[0]);
  if (kind == "product" || kind == "big") return diff_product(in, built);
  if (kind == "synthesis" || kind == "big_synth") return diff_synthesis(plant_parts(in), in.back(), built);
  if (kind == "control") return diff_control(plant_parts(in), in.back());
  if (kind == "observation") {
    if (auto d = diff_observer(in[0])) return d;
    if (auto d = diff_observability(plant_parts(in), in.back())) return d;
    return diff_supcon_normal(plant_parts(in), in.back(), built);
  }
  if (kind == "inclusion") {
    if (auto d = diff_inclusion(in[0], in[1])) return d;
    return diff_inclusion(in[1], in[0]);
  }
  if (kind == "roundtrip") {
    const std::string text = impl::write_fsm(in[0]);
    if (impl::read_fsm(text, "roundtrip") != in[0]) return "reading the written automaton does not give it back:\n" + text;
    return std::nullopt;
  }
  return "unknown case kind " + kind;
}

CampaignReport run_campaign(const CampaignOptions& o) {
  CampaignReport report;
  std::optional<std::pair<Case, std::string>> last_failure;   // the last is the smallest
  const auto property = [&] {
    const Case c = gen_case();
    BuiltSizes built;
    std::optional<std::string> d;
    try {
      d = diff_case(c.kind, c.inputs, &built);
    } catch (const std::exception& e) {   // a crash of either side is a difference too
      d = std::string("an exception: ") + e.what();
    }
    if (d) last_failure.emplace(c, *d);
    else if (!last_failure) note(c, built, report.coverage);
    RC_ASSERT(!d.has_value());
  };
  const CampaignRun run = conformance::run_campaign("automata: impl equals model", o.seed, o.cases, property, o.on_case);
  report.cases_run = run.cases_run;
  if (!last_failure) return report;
  Counterexample cx;
  cx.kind = last_failure->first.kind;
  cx.inputs = reduce(cx.kind, last_failure->first.inputs);
  cx.difference = diff_case(cx.kind, cx.inputs).value_or(last_failure->second);
  cx.shrinks = run.shrinks;
  cx.shrink_tries = run.shrink_tries;
  for (const auto& a : cx.inputs) cx.states += a.states.size();
  cx.files = write_counterexample(o.out_dir, "automata-seed" + std::to_string(o.seed), cx.inputs);
  cx.command = command_for(cx.kind, cx.files);
  report.counterexample = cx;
  return report;
}

}  // namespace swarmcheck::conformance::supervisor
