// `swarmcheck fsm ...`: each subcommand reads its .fsm files, runs one operation on the chosen
// engine (the library by default; the reference model on request, through the harness's engine
// choice) and prints a summary, as text or JSON. Output files are written whole or not at all
// (write_fsm_file: temporary file + rename).
#include "apps/swarmcheck/fsm_verb.hpp"

#include <fmt/format.h>

#include <memory>
#include <nlohmann/json.hpp>

#include "apps/swarmcheck/verb.hpp"
#include "spec/util/hana_json.hpp"
#include "conformance/supervisor/engine.hpp"
#include "views/fsm_svg.hpp"
#include "impl/io/atomic_file.hpp"
#include "swarmcheck/supervisor.hpp"

namespace swarmcheck::cli {

namespace {

namespace sv = swarmcheck::supervisor;
namespace engines = swarmcheck::conformance::supervisor;
using sv::Automaton;
using Json = nlohmann::ordered_json;

struct FsmOptions {
  std::vector<std::string> files;
  std::vector<std::string> plants, specs;
  std::string out;
  std::string to = "fsm";
  std::string engine = "impl";
  bool json = false;
  Budgets budgets;   // --memory-limit of product and synth (the impl engine)
};

void print_json(const Json& j) { fmt::print("{}\n", json_io::dump_text(j, 2)); }

std::vector<Automaton> read_all(const std::vector<std::string>& paths) {
  std::vector<Automaton> out;
  for (const auto& p : paths) out.push_back(sv::read_fsm_file(p));
  return out;
}

int run_check(const FsmOptions& o) {
  const Automaton a = sv::read_fsm_file(o.files.front());
  const sv::CheckReport r = engines::check(a, engines::engine_named(o.engine));
  const std::vector<std::string>& blocking = r.blocking_states;
  const std::vector<std::string>& unreachable = r.unreachable_states;
  const bool coaccessible = r.coaccessible;
  std::size_t controllable = 0;
  for (const auto& [e, attr] : a.events) controllable += attr.controllable ? 1 : 0;
  const bool nonblocking = blocking.empty();
  if (o.json) {
    print_json({{"file", o.files.front()},
                {"states", a.states.size()},
                {"initial", a.states.empty() ? Json(nullptr) : Json(a.states.front())},
                {"marked", a.marked.size()},
                {"events", a.events.size()},
                {"controllable_events", controllable},
                {"transitions", swarmcheck::supervisor::transition_count(a)},
                {"deterministic", true},  // the reader refuses nondeterministic files
                {"accessible", unreachable.empty()},
                {"unreachable_states", unreachable},
                {"coaccessible", coaccessible},
                {"nonblocking", nonblocking},
                {"blocking_states", blocking}});
  } else {
    fmt::print("{}: {} states ({} marked), {} events ({} controllable), {} transitions\n",
               o.files.front(), a.states.size(), a.marked.size(), a.events.size(), controllable,
               swarmcheck::supervisor::transition_count(a));
    fmt::print("deterministic: yes\naccessible: {} ({} unreachable)\ncoaccessible: {}\n",
               unreachable.empty() ? "yes" : "no", unreachable.size(),
               coaccessible ? "yes" : "no");
    fmt::print("nonblocking: {}\n", nonblocking ? "yes" : "no");
    for (const auto& q : blocking) fmt::print("  blocking state: {}\n", q);
  }
  return nonblocking ? 0 : 1;
}

int run_product(const FsmOptions& o) {
  const engines::Engine engine = engines::engine_named(o.engine);
  const Automaton p = engines::product(read_all(o.files), o.files, engine, o.budgets.memory_bytes);
  sv::write_fsm_file(o.out, p);
  if (o.json)
    print_json({{"output", o.out},
                {"states", p.states.size()},
                {"transitions", swarmcheck::supervisor::transition_count(p)},
                {"nonblocking", engines::is_nonblocking(p, engine)}});
  else
    fmt::print("{}: {} states, {} transitions\n", o.out, p.states.size(),
               swarmcheck::supervisor::transition_count(p));
  return 0;
}

int run_synth(const FsmOptions& o) {
  const engines::Engine engine = engines::engine_named(o.engine);
  const Automaton plant = engines::product(read_all(o.plants), o.plants, engine, o.budgets.memory_bytes);
  const Automaton spec = engines::product(read_all(o.specs), o.specs, engine, o.budgets.memory_bytes);
  const Automaton sup = engines::supcon(plant, spec, engine, o.budgets.memory_bytes);
  const bool controllable = engines::is_controllable(plant, spec, engine);
  sv::write_fsm_file(o.out, sup);
  const bool empty = sup.states.empty();
  if (o.json)
    print_json({{"output", o.out},
                {"plant_states", plant.states.size()},
                {"spec_states", spec.states.size()},
                {"spec_controllable", controllable},
                {"states", sup.states.size()},
                {"transitions", swarmcheck::supervisor::transition_count(sup)},
                {"marked", sup.marked.size()},
                {"empty", empty}});
  else
    fmt::print("{}: supervisor of {} states, {} transitions{} (plant {} states, spec {} states, "
               "spec {}controllable as given)\n",
               o.out, sup.states.size(), swarmcheck::supervisor::transition_count(sup),
               empty ? " (EMPTY: no controllable nonblocking behaviour exists)" : "",
               plant.states.size(), spec.states.size(), controllable ? "" : "not ");
  return 0;
}

int run_export(const FsmOptions& o) {
  const Automaton a = sv::read_fsm_file(o.files.front());
  const std::string text = o.to == "dot"    ? sv::to_dot(a)
                           : o.to == "json" ? sv::to_json_text(a)
                           : o.to == "svg"  ? views::fsm_svg(a)
                                            : sv::write_fsm(a);
  if (o.out.empty())
    fmt::print("{}", text);
  else
    impl::io::write_file_atomically(o.out, text);
  return 0;
}

Json witness(const std::vector<std::string>& w) { return Json(w); }

int run_compare(const FsmOptions& o) {
  const Automaton a = sv::read_fsm_file(o.files[0]);
  const Automaton b = sv::read_fsm_file(o.files[1]);
  const engines::Engine engine = engines::engine_named(o.engine);
  const sv::Inclusion ab = engines::language_inclusion(a, b, engine);
  const sv::Inclusion ba = engines::language_inclusion(b, a, engine);
  if (o.json) {
    auto side = [](const sv::Inclusion& i) {
      return Json{{"closed", i.closed},
                  {"marked", i.marked},
                  {"closed_witness", i.closed ? Json(nullptr) : witness(i.closed_witness)},
                  {"marked_witness", i.marked ? Json(nullptr) : witness(i.marked_witness)}};
    };
    print_json({{"a", {{"file", o.files[0]}, {"states", a.states.size()}}},
                {"b", {{"file", o.files[1]}, {"states", b.states.size()}}},
                {"a_in_b", side(ab)},
                {"b_in_a", side(ba)}});
  } else {
    auto line = [](const char* what, const sv::Inclusion& i) {
      fmt::print("{}: L {} (witness: {}), Lm {} (witness: {})\n", what, i.closed ? "yes" : "no",
                 fmt::join(i.closed_witness, " "), i.marked ? "yes" : "no",
                 fmt::join(i.marked_witness, " "));
    };
    fmt::print("A = {} ({} states), B = {} ({} states)\n", o.files[0], a.states.size(),
               o.files[1], b.states.size());
    line("A in B", ab);
    line("B in A", ba);
  }
  return ab.closed && ab.marked && ba.closed && ba.marked ? 0 : 1;
}

void add_engine(CLI::App* sub, FsmOptions& o) {
  sub->add_option("--engine", o.engine, "impl (fast, default) or model (the reference)")
      ->check(CLI::IsMember({"impl", "model"}));
}

}  // namespace

void add_fsm_verb(CLI::App& app, int& exit_code) {
  auto* fsm = app.add_subcommand("fsm", "discrete-event automata in UMDES .fsm files");
  fsm->require_subcommand(1);
  auto o = std::make_shared<FsmOptions>();
  auto wire = [&exit_code, o](CLI::App* sub, int (*body)(const FsmOptions&)) {
    sub->callback([&exit_code, o, body] {
      exit_code = guarded([&] {
        std::vector<std::string> inputs = o->files;
        inputs.insert(inputs.end(), o->plants.begin(), o->plants.end());
        inputs.insert(inputs.end(), o->specs.begin(), o->specs.end());
        impl::io::refuse_output_that_is_an_input(o->out, inputs);
        return body(*o);
      });
    });
  };

  auto* check = fsm->add_subcommand(
      "check", "states, events, accessibility, coaccessibility, blocking states (exit 1 if blocking)");
  check->add_option("file", o->files, "the .fsm file")->required()->expected(1);
  check->add_flag("--json", o->json, "print JSON");
  add_engine(check, *o);
  wire(check, run_check);

  auto* prod = fsm->add_subcommand("product", "synchronous product (accessible part) of automata");
  prod->add_option("files", o->files, "two or more .fsm files")->required()->expected(2, -1);
  prod->add_option("-o,--output", o->out, "the product .fsm to write")->required();
  prod->add_flag("--json", o->json, "print a JSON summary");
  add_engine(prod, *o);
  add_budget_options(prod, o->budgets, false);
  wire(prod, run_product);

  auto* synth = fsm->add_subcommand(
      "synth", "supremal controllable nonblocking supervisor of plants for specifications");
  synth->add_option("--plant", o->plants, "plant component .fsm files")->required()->expected(1, -1);
  synth->add_option("--spec", o->specs, "specification .fsm files")->required()->expected(1, -1);
  synth->add_option("-o,--output", o->out, "the supervisor .fsm to write")->required();
  synth->add_flag("--json", o->json, "print a JSON summary");
  add_engine(synth, *o);
  add_budget_options(synth, o->budgets, false);
  wire(synth, run_synth);

  auto* exp = fsm->add_subcommand("export", "write an automaton as DOT, JSON, canonical .fsm or SVG");
  exp->add_option("file", o->files, "the .fsm file")->required()->expected(1);
  exp->add_option("--to", o->to, "dot, json, fsm or svg (laid out by Graphviz dot)")->check(CLI::IsMember({"dot", "json", "fsm", "svg"}));
  exp->add_option("-o,--output", o->out, "write here instead of standard output");
  wire(exp, run_export);

  auto* cmp = fsm->add_subcommand(
      "compare", "language inclusion both ways, with shortest witnesses (exit 1 if not equal)");
  cmp->add_option("files", o->files, "A.fsm B.fsm")->required()->expected(2);
  cmp->add_flag("--json", o->json, "print JSON");
  add_engine(cmp, *o);
  wire(cmp, run_compare);
}

}  // namespace swarmcheck::cli
