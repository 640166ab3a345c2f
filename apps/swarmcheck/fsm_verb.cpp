// `swarmcheck fsm ...`: each subcommand reads its .fsm files, runs one operation on the chosen
// engine (the library by default; the reference model on request, through the harness's engine
// choice) and prints a summary, as text or JSON. Output files are written whole or not at all
// (write_fsm_file: temporary file + rename).
#include "apps/swarmcheck/fsm_verb.hpp"

#include <fmt/format.h>

#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>

#include "apps/swarmcheck/fsm_control_verb.hpp"
#include "apps/swarmcheck/fsm_peaks.hpp"
#include "apps/swarmcheck/verb.hpp"
#include "spec/util/hana_json.hpp"
#include "conformance/supervisor/engine.hpp"
#include "views/fsm_svg.hpp"
#include "impl/io/atomic_file.hpp"
#include "impl/supervisor/fsm_compact_io.hpp"
#include "impl/supervisor/operations.hpp"
#include "swarmcheck/supervisor.hpp"

namespace swarmcheck::cli {

namespace {

namespace sv = swarmcheck::supervisor;
namespace engines = swarmcheck::conformance::supervisor;
namespace is = swarmcheck::impl::supervisor;
using sv::Automaton;
using Json = nlohmann::ordered_json;

struct FsmOptions {
  std::vector<std::string> files;
  std::vector<std::string> plants, specs;
  std::string out;
  std::string to = "fsm";
  std::string engine = "impl";
  bool json = false;
  Budgets budgets;   // --memory-limit, --time-limit of product, synth and compare (the impl engine)
};

void print_json(const Json& j) { fmt::print("{}\n", json_io::dump_text(j, 2)); }

// The files of one command are read together: an attribute one leaves unstated comes from
// another that states it (spec/supervisor/attributes.hpp).
std::vector<Automaton> read_all(const std::vector<std::string>& paths) {
  return sv::read_fsm_files(paths);
}

// The library's engine works on the compact form (is::Fsm) from the file to the output: no
// Automaton value, whose maps of strings cost gigabytes at millions of states. The model's
// engine works on values; both print through the same code, so their outputs are alike.
std::vector<is::Fsm> read_all_compact(const std::vector<std::string>& paths) {
  return is::read_fsm_compact_files(paths);
}

// Plants then specifications, read together, split back.
template <class T>
std::pair<std::vector<T>, std::vector<T>> split_plants_specs(std::vector<T> all, std::size_t plants) {
  std::vector<T> specs(std::make_move_iterator(all.begin() + static_cast<std::ptrdiff_t>(plants)),
                       std::make_move_iterator(all.end()));
  all.resize(plants);
  return {std::move(all), std::move(specs)};
}

std::vector<std::string> plants_then_specs(const FsmOptions& o) {
  std::vector<std::string> all = o.plants;
  all.insert(all.end(), o.specs.begin(), o.specs.end());
  return all;
}

std::vector<const is::Fsm*> pointers(const std::vector<is::Fsm>& fs) {
  std::vector<const is::Fsm*> out;
  for (const auto& f : fs) out.push_back(&f);
  return out;
}

std::size_t count_set(const std::vector<std::uint8_t>& flags) {
  std::size_t n = 0;
  for (const auto b : flags) n += b ? 1 : 0;
  return n;
}

// What `fsm check` prints, from either engine.
struct CheckFacts {
  std::size_t states = 0, marked = 0, events = 0, controllable = 0, transitions = 0;
  std::optional<std::string> initial;
  sv::CheckReport report;
};

CheckFacts check_facts(const std::string& path, engines::Engine engine) {
  CheckFacts c;
  if (engine == engines::Engine::impl) {
    const is::Fsm f = is::read_fsm_compact_file(path);
    c.report = is::check(f);
    c.states = f.state_count();
    c.marked = count_set(f.marked);
    c.events = f.event_count();
    c.controllable = count_set(f.controllable);
    c.transitions = f.edge_count();
    if (f.state_count() > 0) c.initial = f.state_names.front();
    return c;
  }
  const Automaton a = sv::read_fsm_file(path);
  c.report = engines::check(a, engine);
  c.states = a.states.size();
  c.marked = a.marked.size();
  c.events = a.events.size();
  for (const auto& [e, attr] : a.events) c.controllable += attr.controllable ? 1 : 0;
  c.transitions = swarmcheck::supervisor::transition_count(a);
  if (!a.states.empty()) c.initial = a.states.front();
  return c;
}

int run_check(const FsmOptions& o) {
  const CheckFacts c = check_facts(o.files.front(), engines::engine_named(o.engine));
  const std::vector<std::string>& blocking = c.report.blocking_states;
  const std::vector<std::string>& unreachable = c.report.unreachable_states;
  const bool coaccessible = c.report.coaccessible;
  const bool nonblocking = blocking.empty();
  if (o.json) {
    print_json({{"file", o.files.front()},
                {"states", c.states},
                {"initial", c.initial ? Json(*c.initial) : Json(nullptr)},
                {"marked", c.marked},
                {"events", c.events},
                {"controllable_events", c.controllable},
                {"transitions", c.transitions},
                {"deterministic", true},  // the reader refuses nondeterministic files
                {"accessible", unreachable.empty()},
                {"unreachable_states", unreachable},
                {"coaccessible", coaccessible},
                {"nonblocking", nonblocking},
                {"blocking_states", blocking}});
  } else {
    fmt::print("{}: {} states ({} marked), {} events ({} controllable), {} transitions\n",
               o.files.front(), c.states, c.marked, c.events, c.controllable, c.transitions);
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
  std::size_t states = 0, transitions = 0;
  std::function<bool()> nonblocking;  // only asked for --json
  std::vector<is::Fsm> parts;
  is::Product compact;
  Automaton p;
  if (engine == engines::Engine::impl) {
    parts = read_all_compact(o.files);
    WorkBudget work = o.budgets.work();
    compact = is::product_with_tuples(pointers(parts), o.files, work,
                                      fsm_peaks::product_command(parts.size(), fsm_peaks::bytes_of(parts)));
    is::write_fsm_compact_file(o.out, compact.fsm, is::name_speller(compact.fsm, &compact.names));
    states = compact.fsm.state_count();
    transitions = compact.fsm.edge_count();
    // A product holds only accessible states: nonblocking is coaccessibility of them all.
    nonblocking = [&] { return is::every_state_coaccessible(compact.fsm); };
    report_memory(o.budgets, work.peak_estimate());
  } else {
    p = engines::product(read_all(o.files), o.files, engine, o.budgets.memory_bytes);
    sv::write_fsm_file(o.out, p);
    states = p.states.size();
    transitions = swarmcheck::supervisor::transition_count(p);
    nonblocking = [&] { return engines::is_nonblocking(p, engine); };
  }
  if (o.json)
    print_json({{"output", o.out},
                {"states", states},
                {"transitions", transitions},
                {"nonblocking", nonblocking()}});
  else
    fmt::print("{}: {} states, {} transitions\n", o.out, states, transitions);
  return 0;
}

// What `fsm synth` prints, from either engine.
// With `uo` events in the plant or the specification, synth gives the supremal controllable and
// normal supervisor (spec/supervisor/observation.hpp); without, the supremal controllable one.
struct SynthFacts {
  std::size_t plant_states = 0, spec_states = 0, states = 0, transitions = 0, marked = 0;
  bool controllable = true;
  std::vector<std::string> unobservable;   // the `uo` events of plant and spec, in name order
};

std::vector<std::string> unobservable_of(const is::Fsm& plant, const is::Fsm& spec) {
  std::set<std::string> out;
  for (const is::Fsm* f : {&plant, &spec})
    for (is::EventId e = 0; e < f->event_count(); ++e)
      if (!f->observable[e]) out.insert(f->event_names[e]);
  return {out.begin(), out.end()};
}

// A budget stopped inside the library names its construction ("plant || spec"); the user's
// message names the files.
template <class F>
auto naming_files(const FsmOptions& o, F&& f) {
  try {
    return f();
  } catch (const BudgetExceeded& e) {
    std::string files;
    for (const auto& p : plants_then_specs(o)) files += (files.empty() ? "" : " || ") + p;
    throw BudgetExceeded(files, std::string(e.what()).substr(e.where().size() + 2));
  }
}

SynthFacts synth_compact(const FsmOptions& o) {
  const auto [plants, specs] = split_plants_specs(read_all_compact(plants_then_specs(o)), o.plants.size());
  WorkBudget work = o.budgets.work();
  const double inputs = fsm_peaks::bytes_of(plants) + fsm_peaks::bytes_of(specs);
  const is::Fsm plant = is::product(pointers(plants), o.plants, work, fsm_peaks::product_command(plants.size(), inputs, true));
  const is::Fsm spec = is::product(pointers(specs), o.specs, work, fsm_peaks::product_command(specs.size(), inputs, true));
  const double held = fsm_peaks::bytes_of(plant) + fsm_peaks::bytes_of(spec) + inputs;
  const std::vector<std::string> unobservable = unobservable_of(plant, spec);
  if (!unobservable.empty()) {
    const is::Fsm sup = naming_files(o, [&] {
      return is::supcon_normal(plant, spec, work, fsm_peaks::normal_synth_command(held, plant.event_count() + spec.event_count()));
    });
    is::write_fsm_compact_file(o.out, sup, is::name_speller(sup));
    const bool controllable = naming_files(o, [&] { return is::is_controllable(plant, spec, work, fsm_peaks::synth_command(held)); });
    report_memory(o.budgets, work.peak_estimate());
    return {plant.state_count(), spec.state_count(), sup.state_count(), sup.edge_count(),
            count_set(sup.marked), controllable, unobservable};
  }
  const is::Synthesis sup = naming_files(o, [&] { return is::synthesize(plant, spec, work, fsm_peaks::synth_command(held)); });
  is::write_fsm_compact_file(o.out, sup.supervisor, is::name_speller(sup.supervisor, &sup.names));
  report_memory(o.budgets, work.peak_estimate());
  return {plant.state_count(), spec.state_count(), sup.supervisor.state_count(),
          sup.supervisor.edge_count(), count_set(sup.supervisor.marked), sup.spec_controllable, {}};
}

SynthFacts synth_values(const FsmOptions& o, engines::Engine engine) {
  const auto [plants, specs] = split_plants_specs(read_all(plants_then_specs(o)), o.plants.size());
  const Automaton plant = engines::product(plants, o.plants, engine, o.budgets.memory_bytes);
  const Automaton spec = engines::product(specs, o.specs, engine, o.budgets.memory_bytes);
  std::set<std::string> uo;
  for (const Automaton* a : {&plant, &spec})
    for (const auto& e : sv::unobservable_events(a->events)) uo.insert(e);
  const Automaton sup = uo.empty() ? engines::supcon(plant, spec, engine, o.budgets.memory_bytes)
                                   : naming_files(o, [&] { return engines::supcon_normal(plant, spec, engine, o.budgets.memory_bytes); });
  const bool controllable = engines::is_controllable(plant, spec, engine);
  sv::write_fsm_file(o.out, sup);
  return {plant.states.size(), spec.states.size(), sup.states.size(),
          swarmcheck::supervisor::transition_count(sup), sup.marked.size(), controllable,
          {uo.begin(), uo.end()}};
}

int run_synth(const FsmOptions& o) {
  const engines::Engine engine = engines::engine_named(o.engine);
  const SynthFacts s = engine == engines::Engine::impl ? synth_compact(o) : synth_values(o, engine);
  const bool empty = s.states == 0;
  if (o.json)
    print_json({{"output", o.out},
                {"plant_states", s.plant_states},
                {"spec_states", s.spec_states},
                {"spec_controllable", s.controllable},
                {"states", s.states},
                {"transitions", s.transitions},
                {"marked", s.marked},
                {"empty", empty},
                {"normal", !s.unobservable.empty()},
                {"unobservable_events", s.unobservable}});
  else
    fmt::print("{}: {}supervisor of {} states, {} transitions{} (plant {} states, spec {} states, "
               "spec {}controllable as given){}\n",
               o.out, s.unobservable.empty() ? "" : "normal ", s.states, s.transitions,
               !empty                   ? ""
               : s.unobservable.empty() ? " (EMPTY: no controllable nonblocking behaviour exists)"
                                        : " (EMPTY: no controllable, normal, nonblocking behaviour exists)",
               s.plant_states, s.spec_states, s.controllable ? "" : "not ",
               s.unobservable.empty() ? ""
                                      : fmt::format("; unobservable events: {}",
                                                    fmt::join(s.unobservable, " ")));
  return 0;
}

int run_export(const FsmOptions& o) {
  const Automaton a = sv::read_fsm_file(o.files.front());
  // dot takes minutes (and gigabytes, or crashes) on big automata: refused, as `view` declines.
  if (const std::size_t n = sv::transition_count(a); o.to == "svg" && n > views::kLayoutTransitionsMax)
    throw InputError(o.files.front(), fmt::format("{} transitions, more than the {} that dot lays out in reasonable time: "
                                                  "export --to dot and lay it out yourself, or `swarmcheck view` it (a "
                                                  "searchable list)", n, views::kLayoutTransitionsMax));
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
  const engines::Engine engine = engines::engine_named(o.engine);
  std::size_t a_states = 0, b_states = 0;
  sv::Inclusion ab, ba;
  if (engine == engines::Engine::impl) {
    const is::Fsm a = is::read_fsm_compact_file(o.files[0]);
    const is::Fsm b = is::read_fsm_compact_file(o.files[1]);
    a_states = a.state_count();
    b_states = b.state_count();
    // Up to |A| x (|B| + 1) pairs each way: budgeted, one way at a time.
    WorkBudget work = o.budgets.work();
    const auto peak = fsm_peaks::compare_pairs(fsm_peaks::bytes_of(a) + fsm_peaks::bytes_of(b));
    const std::string both = o.files[0] + ", " + o.files[1];
    const auto naming = [&](auto&& f) {
      try {
        return f();
      } catch (const BudgetExceeded& e) {
        throw BudgetExceeded(both, std::string(e.what()).substr(e.where().size() + 2));
      }
    };
    ab = naming([&] { return is::language_inclusion(a, b, work, peak); });
    ba = naming([&] { return is::language_inclusion(b, a, work, peak); });
    report_memory(o.budgets, work.peak_estimate());
  } else {
    const Automaton a = sv::read_fsm_file(o.files[0]);
    const Automaton b = sv::read_fsm_file(o.files[1]);
    a_states = a.states.size();
    b_states = b.states.size();
    ab = engines::language_inclusion(a, b, engine);
    ba = engines::language_inclusion(b, a, engine);
  }
  if (o.json) {
    auto side = [](const sv::Inclusion& i) {
      return Json{{"closed", i.closed},
                  {"marked", i.marked},
                  {"closed_witness", i.closed ? Json(nullptr) : witness(i.closed_witness)},
                  {"marked_witness", i.marked ? Json(nullptr) : witness(i.marked_witness)}};
    };
    print_json({{"a", {{"file", o.files[0]}, {"states", a_states}}},
                {"b", {{"file", o.files[1]}, {"states", b_states}}},
                {"a_in_b", side(ab)},
                {"b_in_a", side(ba)}});
  } else {
    auto line = [](const char* what, const sv::Inclusion& i) {
      fmt::print("{}: L {} (witness: {}), Lm {} (witness: {})\n", what, i.closed ? "yes" : "no",
                 fmt::join(i.closed_witness, " "), i.marked ? "yes" : "no",
                 fmt::join(i.marked_witness, " "));
    };
    fmt::print("A = {} ({} states), B = {} ({} states)\n", o.files[0], a_states,
               o.files[1], b_states);
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
  add_time_limit_option(prod, o->budgets);
  wire(prod, run_product);

  auto* synth = fsm->add_subcommand(
      "synth", "supremal controllable nonblocking supervisor of plants for specifications (also "
              "normal when an event is uo)");
  synth->add_option("--plant", o->plants, "plant component .fsm files")->required()->expected(1, -1);
  synth->add_option("--spec", o->specs, "specification .fsm files")->required()->expected(1, -1);
  synth->add_option("-o,--output", o->out, "the supervisor .fsm to write")->required();
  synth->add_flag("--json", o->json, "print a JSON summary");
  add_engine(synth, *o);
  add_budget_options(synth, o->budgets, false);
  add_time_limit_option(synth, o->budgets);
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
  add_budget_options(cmp, o->budgets, false);
  add_time_limit_option(cmp, o->budgets);
  wire(cmp, run_compare);

  add_fsm_control_subcommands(fsm, exit_code);
}

}  // namespace swarmcheck::cli
