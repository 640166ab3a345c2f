#include "conformance/supervisor/campaign.hpp"
#include "spec/util/json_text.hpp"

#include <rapidcheck.h>

#include <algorithm>
#include <cmath>

#include "conformance/common/child_process.hpp"
#include "conformance/supervisor/counterexample.hpp"
#include "conformance/supervisor/differential.hpp"
#include "conformance/supervisor/generators.hpp"
#include "impl/supervisor/fsm_io.hpp"
#include "impl/supervisor/operations.hpp"
#include "model/supervisor/control.hpp"
#include "model/supervisor/observation.hpp"
#include "model/supervisor/operations.hpp"
#include <nlohmann/json.hpp>

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


// One case's comparison: its difference (an exception, a crash or a hang included: "the case
// crashed with SIGSEGV"), what it built, and whether L(a) is in L(b) for an inclusion case
// (coverage).
struct Isolated {
  std::optional<std::string> difference;
  BuiltSizes built;
  bool inclusion_fails = false;
  bool abnormal = false;   // a crash, a hang, an exit: the side is not known yet
  bool hung = false;
};

// The comparison in this process.
Isolated diff_here(const std::string& kind, const std::vector<Automaton>& in) {
  Isolated out;
  try {
    out.difference = diff_case(kind, in, &out.built);
    out.inclusion_fails = kind == "inclusion" && !out.difference &&
                          !impl::language_inclusion(impl::compile(in[0]), impl::compile(in[1])).closed;
  } catch (const std::exception& e) {   // an exception on either side is a difference too
    out.difference = std::string("an exception: ") + e.what();
  }
  return out;
}

// The comparison in a child process of its own (conformance/common/child_process.hpp).
Isolated diff_isolated(const std::string& kind, const std::vector<Automaton>& in, std::chrono::milliseconds quiet) {
  const ChildEnd end = run_in_child([&](CaseProgress& p) {
    p.alive();
    const Isolated here = diff_here(kind, in);
    nlohmann::json j;
    if (here.difference) j["difference"] = *here.difference;
    j["built"] = {here.built.product_states, here.built.supervisor_states};
    j["inclusion_fails"] = here.inclusion_fails;
    return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  }, ChildLimits{quiet});
  Isolated out;
  out.hung = end.how == ChildEnd::How::hung;
  if (!end.finished()) {
    out.difference = end.describe();
    out.abnormal = true;
    return out;
  }
  const nlohmann::json j = swarmcheck::json_io::parse_json_text(end.output, "the campaign's child process");
  if (j.contains("difference")) out.difference = j["difference"].get<std::string>();
  out.built = BuiltSizes{j["built"][0].get<std::size_t>(), j["built"][1].get<std::size_t>()};
  out.inclusion_fails = j["inclusion_fails"].get<bool>();
  return out;
}

// Where a campaign runs its cases: in this process (`here`, itself a child: the first pass) or
// each in a child of its own (the second pass).
struct Runner {
  CaseProgress* here;
  std::chrono::milliseconds quiet;
  Isolated operator()(const std::string& kind, const std::vector<Automaton>& in) const {
    if (!here) return diff_isolated(kind, in, quiet);
    here->alive();
    return diff_here(kind, in);
  }
};

// The model's side of a case alone (what diff_case computes with the model), to tell whose a
// crash or a hang was: when the model alone runs the case to its end, it was the library's.
void model_side(const std::string& kind, const std::vector<Automaton>& in) {
  const auto plant = [&] {
    const std::vector<Automaton> parts = plant_parts(in);
    if (parts.size() == 1) return parts[0];
    std::vector<std::string> names;
    for (std::size_t i = 0; i < parts.size(); ++i) names.push_back("part " + std::to_string(i + 1));
    return model::product(parts, names);
  };
  if (kind == "unary") {
    (void)model::accessible_states(in[0]);
    (void)model::coaccessible_states(in[0]);
    (void)model::blocking_states(in[0]);
    (void)model::trim(in[0]);
    (void)model::accessible_part(in[0]);
  } else if (kind == "product" || kind == "big") {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < in.size(); ++i) names.push_back("part " + std::to_string(i + 1));
    (void)model::product(in, names);
  } else if (kind == "synthesis" || kind == "big_synth") {
    const Automaton g = plant();
    (void)model::is_controllable(g, in.back());
    (void)model::supcon(g, in.back());
  } else if (kind == "control") {
    (void)model::control_report(plant(), in.back());
  } else if (kind == "observation") {
    (void)model::observer(in[0]);
    const Automaton g = plant();
    (void)model::observability(g, in.back());
    (void)model::supcon_normal(g, in.back());
  } else if (kind == "inclusion") {
    (void)model::language_inclusion(in[0], in[1]);
    (void)model::language_inclusion(in[1], in[0]);
  }
}

// "the case crashed with ..." becomes "impl crashed with ..." when the model alone gets through
// the case (or "model ..." when it does not).
std::string attributed(const std::string& kind, const std::vector<Automaton>& in, const std::string& abnormal,
                       std::chrono::milliseconds quiet) {
  const std::string prefix = "the case ";
  if (abnormal.rfind(prefix, 0) != 0) return abnormal;
  const ChildEnd model_alone = run_in_child([&](CaseProgress& p) {
    p.alive();
    model_side(kind, in);
    return std::string();
  }, ChildLimits{quiet});
  return (model_alone.finished() ? "impl " : "model ") + abnormal.substr(prefix.size()) +
         (model_alone.finished() ? " (the model alone runs the case to its end)" : "");
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
}

// Without the states no input reaches, and without events no transition uses, when the
// difference stays: what is left is the part of the counterexample that matters.
std::vector<Automaton> reduce(const std::string& kind, std::vector<Automaton> in, const Runner& run) {
  // A try that hangs costs the whole time limit: it is not taken, and the reduction stops there.
  bool hung = false;
  const auto differs = [&](const std::vector<Automaton>& tried) {
    if (hung) return false;
    const Isolated r = run(kind, tried);
    hung = r.hung;
    return r.difference.has_value() && !r.hung;
  };
  for (std::size_t i = 0; i < in.size(); ++i) {
    std::vector<Automaton> tried = in;
    tried[i] = model::accessible_part(tried[i]);
    if (tried[i] != in[i] && differs(tried)) in = tried;
    for (const auto& [e, attr] : Alphabet(in[i].events)) {
      bool used = false;
      for (const auto& [q, row] : in[i].delta) used = used || row.count(e) > 0;
      if (used) continue;
      tried = in;
      tried[i].events.erase(e);
      if (differs(tried)) in = tried;
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

namespace {

// The campaign, its cases run by `run` (in this process, itself a child, or each in a child of
// its own: then the first `skip` cases, which the first pass saw agree, are not run again).
CampaignReport run_cases(const CampaignOptions& o, const Runner& run, int64_t skip) {
  CampaignReport report;
  std::optional<std::pair<Case, std::string>> last_failure;   // the last is the smallest
  std::string caught_by;
  int64_t first_cases = 0;   // cases drawn before the first failure
  const auto property = [&](CaseBudget& budget) {
    const Case c = gen_case();
    if (!last_failure && ++first_cases <= skip) return;
    const Isolated r = run(c.kind, c.inputs);
    if (r.hung) budget.hung();
    if (run.here && !r.difference && !last_failure) run.here->agreed(first_cases);
    if (r.difference && !last_failure) caught_by = c.kind;
    if (r.difference) {
      last_failure.emplace(c, *r.difference);
    } else if (!last_failure) {
      note(c, r.built, report.coverage);
      report.coverage.inclusions_failing += r.inclusion_fails ? 1 : 0;
    }
    RC_ASSERT(!r.difference.has_value());
  };
  const CampaignRun campaign = conformance::run_campaign("automata: impl equals model", o.seed, o.cases, property,
                                                         o.on_case, ShrinkBudget{});
  report.cases_run = campaign.cases_run;
  if (!last_failure) return report;
  Counterexample cx;
  cx.kind = last_failure->first.kind;
  cx.caught_by = caught_by;
  cx.inputs = reduce(cx.kind, last_failure->first.inputs, run);
  const Isolated again = run(cx.kind, cx.inputs);
  cx.difference = again.difference.value_or(last_failure->second);
  if (again.abnormal) cx.difference = attributed(cx.kind, cx.inputs, cx.difference, o.quiet_limit);
  cx.shrinks = campaign.shrinks;
  cx.shrink_tries = campaign.shrink_tries;
  for (const auto& a : cx.inputs) cx.states += a.states.size();
  cx.files = write_counterexample(o.out_dir, "automata-seed" + std::to_string(o.seed), cx.inputs);
  cx.command = command_for(cx.kind, cx.files);
  report.counterexample = cx;
  return report;
}

nlohmann::json automaton_json(const Automaton& a) {
  nlohmann::json events = nlohmann::json::object();
  for (const auto& [e, attr] : a.events) events[e] = {attr.controllable, attr.observable};
  return {{"states", a.states}, {"marked", a.marked}, {"events", events}, {"delta", a.delta}};
}

Automaton automaton_of(const nlohmann::json& j) {
  Automaton a;
  a.states = j.at("states").get<std::vector<std::string>>();
  a.marked = j.at("marked").get<std::set<std::string>>();
  for (auto it = j.at("events").begin(); it != j.at("events").end(); ++it)
    a.events[it.key()] = EventAttr{it.value()[0].get<bool>(), it.value()[1].get<bool>()};
  a.delta = j.at("delta").get<std::map<std::string, std::map<std::string, std::string>>>();
  return a;
}

// The campaign's report, from the child that ran it to its parent.
std::string report_text(const CampaignReport& r) {
  const Coverage& v = r.coverage;
  nlohmann::json j{{"cases_run", r.cases_run},
                   {"coverage", {{"cases_by_kind", v.cases_by_kind}, {"largest_unary_states", v.largest_unary_states},
                                 {"largest_product_states", v.largest_product_states},
                                 {"largest_plant_states", v.largest_plant_states},
                                 {"largest_supervisor_states", v.largest_supervisor_states},
                                 {"empty_supervisors", v.empty_supervisors},
                                 {"inclusions_failing", v.inclusions_failing}}}};
  if (const auto& x = r.counterexample) {
    nlohmann::json inputs = nlohmann::json::array();
    for (const auto& a : x->inputs) inputs.push_back(automaton_json(a));
    j["counterexample"] = {{"kind", x->kind},       {"caught_by", x->caught_by}, {"difference", x->difference},
                           {"inputs", inputs},       {"files", x->files},         {"command", x->command},
                           {"shrinks", x->shrinks}, {"shrink_tries", x->shrink_tries}, {"states", x->states}};
  }
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

CampaignReport read_report(const std::string& text) {
  const nlohmann::json j = swarmcheck::json_io::parse_json_text(text, "the campaign's report");
  CampaignReport r;
  r.cases_run = j.at("cases_run").get<int>();
  const nlohmann::json& v = j.at("coverage");
  r.coverage.cases_by_kind = v.at("cases_by_kind").get<std::map<std::string, int>>();
  r.coverage.largest_unary_states = v.at("largest_unary_states").get<std::size_t>();
  r.coverage.largest_product_states = v.at("largest_product_states").get<std::size_t>();
  r.coverage.largest_plant_states = v.at("largest_plant_states").get<std::size_t>();
  r.coverage.largest_supervisor_states = v.at("largest_supervisor_states").get<std::size_t>();
  r.coverage.empty_supervisors = v.at("empty_supervisors").get<int>();
  r.coverage.inclusions_failing = v.at("inclusions_failing").get<int>();
  if (j.contains("counterexample")) {
    const nlohmann::json& c = j["counterexample"];
    Counterexample x;
    x.kind = c.at("kind").get<std::string>();
    x.caught_by = c.at("caught_by").get<std::string>();
    x.difference = c.at("difference").get<std::string>();
    for (const auto& a : c.at("inputs")) x.inputs.push_back(automaton_of(a));
    x.files = c.at("files").get<std::vector<std::string>>();
    x.command = c.at("command").get<std::string>();
    x.shrinks = c.at("shrinks").get<int>();
    x.shrink_tries = c.at("shrink_tries").get<int>();
    x.states = c.at("states").get<std::size_t>();
    r.counterexample = x;
  }
  return r;
}

}  // namespace

std::optional<std::string> diff_case_isolated(const std::string& kind, const std::vector<Automaton>& in,
                                              std::chrono::milliseconds quiet_limit) {
  const Isolated r = diff_isolated(kind, in, quiet_limit);
  if (r.abnormal) return attributed(kind, in, *r.difference, quiet_limit);
  return r.difference;
}

CampaignReport run_campaign(const CampaignOptions& o) {
  // First the whole campaign in one child; if the library crashed or hung in it, again with each
  // case in a child of its own, so that the case that crashes shrinks like any other.
  const FirstPass first = run_campaign_in_child(
      [&](CaseProgress& p) { return report_text(run_cases(o, Runner{&p, o.quiet_limit}, 0)); },
      ChildLimits{o.quiet_limit});
  if (first.report) return read_report(*first.report);
  return run_cases(o, Runner{nullptr, o.quiet_limit}, first.cases_agreed);
}

}  // namespace swarmcheck::conformance::supervisor
