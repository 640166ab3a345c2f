// `swarmcheck fsm controllable`: sup as a supervisor of the plant (the product of the plant
// files): controllable? the closed loop nonblocking? each with its shortest witness.
// `fsm observable`: is the specification observable for the plant? `fsm project`: the observer.
// The files of one command are read together, so a specification's unstated attributes come
// from the plant.
#include "apps/swarmcheck/fsm_control_verb.hpp"

#include <fmt/format.h>

#include <iostream>
#include <memory>
#include <set>
#include <nlohmann/json.hpp>

#include "apps/swarmcheck/fsm_peaks.hpp"
#include "apps/swarmcheck/verb.hpp"
#include "conformance/supervisor/engine.hpp"
#include "impl/io/atomic_file.hpp"
#include "impl/supervisor/fsm.hpp"
#include "impl/supervisor/fsm_compact_io.hpp"
#include "impl/supervisor/operations.hpp"
#include "spec/util/hana_json.hpp"
#include "swarmcheck/supervisor.hpp"

namespace swarmcheck::cli {

namespace fsm_control {  // named, not anonymous: fsm_verb.cpp shares this unity build

namespace sv = swarmcheck::supervisor;
namespace engines = swarmcheck::conformance::supervisor;
namespace is = swarmcheck::impl::supervisor;
using Json = nlohmann::ordered_json;

struct Options {
  std::vector<std::string> plants, specs;
  std::string sup, file, out;
  bool json = false;
  std::string engine = "impl";
  Budgets budgets;   // --memory-limit, --time-limit of controllable, observable, project (the impl engine)
};

void print_json(const Json& j) { fmt::print("{}\n", json_io::dump_text(j, 2)); }

struct Sizes {
  std::size_t plant_states = 0, sup_states = 0;
};

// A budget stopped inside the library names its construction ("plant || spec"); the user's
// message names the files.
template <class F>
auto renamed(const std::vector<std::string>& plants, const std::vector<std::string>& others, F&& f) {
  try {
    return f();
  } catch (const BudgetExceeded& e) {
    std::string files;
    for (const auto& p : plants) files += (files.empty() ? "" : " || ") + p;
    for (const auto& p : others) files += " || " + p;
    throw BudgetExceeded(files, std::string(e.what()).substr(e.where().size() + 2));
  }
}
template <class F>
auto renamed(const std::vector<std::string>& plants, const std::string& other, F&& f) {
  return renamed(plants, std::vector<std::string>{other}, std::forward<F>(f));
}

sv::ControlReport report(const Options& o, Sizes& sizes) {
  std::vector<std::string> paths = o.plants;
  paths.push_back(o.sup);
  const engines::Engine engine = engines::engine_named(o.engine);
  if (engine == engines::Engine::impl) {
    std::vector<is::Fsm> all = is::read_fsm_compact_files(paths);
    std::vector<const is::Fsm*> plants;
    for (std::size_t i = 0; i + 1 < all.size(); ++i) plants.push_back(&all[i]);
    WorkBudget work = o.budgets.work();
    const double inputs = fsm_peaks::bytes_of(all);
    const is::Fsm plant = is::product(plants, o.plants, work, fsm_peaks::product_command(plants.size(), inputs, true));
    sizes = {plant.state_count(), all.back().state_count()};
    const auto r = renamed(o.plants, o.sup, [&] {
      return is::control_report(plant, all.back(), work, fsm_peaks::controllable_command(inputs + fsm_peaks::bytes_of(plant)));
    });
    report_memory(o.budgets, work.peak_estimate());
    return r;
  }
  std::vector<sv::Automaton> all = sv::read_fsm_files(paths);
  const sv::Automaton sup = all.back();
  all.pop_back();
  const sv::Automaton plant = engines::product(all, o.plants, engine);
  sizes = {plant.states.size(), sup.states.size()};
  return engines::control_report(plant, sup, engine);
}

std::string words(const std::vector<std::string>& w) {
  return w.empty() ? "the empty word" : fmt::format("{}", fmt::join(w, " "));
}

int run_controllable(const Options& o) {
  Sizes n;
  const sv::ControlReport r = report(o, n);
  if (o.json) {
    print_json(Json{{"plant", o.plants},
             {"supervisor", o.sup},
             {"plant_states", n.plant_states},
             {"supervisor_states", n.sup_states},
             {"closed_loop_states", r.closed_loop_states},
             {"controllable", r.controllable},
             {"witness", r.controllable ? Json(nullptr) : Json(r.witness)},
             {"disabled_event", r.controllable ? Json(nullptr) : Json(r.disabled_event)},
             {"nonblocking", r.nonblocking},
             {"blocking_witness", r.nonblocking ? Json(nullptr) : Json(r.blocking_witness)}});
  } else {
    fmt::print("plant: {} states ({} files); supervisor {}: {} states; closed loop: {} states\n",
               n.plant_states, o.plants.size(), o.sup, n.sup_states, r.closed_loop_states);
    fmt::print("controllable: {}\n", r.controllable ? "yes" : "no");
    if (!r.controllable)
      fmt::print("  after {}, the plant can do the uncontrollable event {}, which the supervisor "
                 "disables\n", words(r.witness), r.disabled_event);
    fmt::print("nonblocking closed loop: {}\n", r.nonblocking ? "yes" : "no");
    if (!r.nonblocking)
      fmt::print("  after {}, no marked state can be reached\n", words(r.blocking_witness));
  }
  return r.controllable && r.nonblocking ? 0 : 1;
}

// Plants and specifications read together, each side's product taken on the chosen engine.
std::pair<sv::Automaton, sv::Automaton> plant_and_spec(const Options& o, engines::Engine engine) {
  std::vector<std::string> paths = o.plants;
  paths.insert(paths.end(), o.specs.begin(), o.specs.end());
  std::vector<sv::Automaton> all = sv::read_fsm_files(paths);
  std::vector<sv::Automaton> specs(all.begin() + static_cast<std::ptrdiff_t>(o.plants.size()), all.end());
  all.resize(o.plants.size());
  return {engines::product(all, o.plants, engine), engines::product(specs, o.specs, engine)};
}

// The library's engine on the compact form, budgeted: plant || spec, then the pairs of its states
// (quadratic: a 1 000-state chain on one unobservable event took 30 s and 2 GB).
sv::ObservabilityReport observability_compact(const Options& o, std::set<std::string>& uo) {
  std::vector<std::string> paths = o.plants;
  paths.insert(paths.end(), o.specs.begin(), o.specs.end());
  std::vector<is::Fsm> all = is::read_fsm_compact_files(paths);
  std::vector<const is::Fsm*> plants, specs;
  for (std::size_t i = 0; i < all.size(); ++i) (i < o.plants.size() ? plants : specs).push_back(&all[i]);
  WorkBudget work = o.budgets.work();
  const double inputs = fsm_peaks::bytes_of(all);
  const is::Fsm plant = is::product(plants, o.plants, work, fsm_peaks::product_command(plants.size(), inputs, true));
  const is::Fsm spec = is::product(specs, o.specs, work, fsm_peaks::product_command(specs.size(), inputs, true));
  for (const is::Fsm* f : {&plant, &spec})
    for (is::EventId e = 0; e < f->event_count(); ++e)
      if (!f->observable[e]) uo.insert(f->event_names[e]);
  const double held = inputs + fsm_peaks::bytes_of(plant) + fsm_peaks::bytes_of(spec);
  const auto r = renamed(o.plants, o.specs, [&] {
    return is::observability(plant, spec, work, fsm_peaks::observable_product(held), fsm_peaks::observable_pairs());
  });
  report_memory(o.budgets, work.peak_estimate());
  return r;
}

int run_observable(const Options& o) {
  const engines::Engine engine = engines::engine_named(o.engine);
  std::set<std::string> uo;
  sv::ObservabilityReport r;
  if (engine == engines::Engine::impl) {
    r = observability_compact(o, uo);
  } else {
    const auto [plant, spec] = plant_and_spec(o, engine);
    r = engines::observability(plant, spec, engine);
    for (const sv::Automaton* a : {&plant, &spec})
      for (const auto& e : sv::unobservable_events(a->events)) uo.insert(e);
  }
  const std::vector<std::string> unobservable(uo.begin(), uo.end());
  if (o.json) {
    print_json(Json{{"plant", o.plants},
                    {"spec", o.specs},
                    {"unobservable_events", unobservable},
                    {"observable", r.observable},
                    {"word", r.observable ? Json(nullptr) : Json(r.word)},
                    {"twin", r.observable ? Json(nullptr) : Json(r.twin)},
                    {"event", r.observable ? Json(nullptr) : Json(r.event)}});
  } else {
    fmt::print("unobservable events: {}\nobservable: {}\n",
               unobservable.empty() ? "(none)" : fmt::format("{}", fmt::join(unobservable, " ")),
               r.observable ? "yes" : "no");
    if (!r.observable)
      fmt::print("  {} and {} look the same to a supervisor; the specification allows the "
                 "controllable event {} after the first and disables it after the second, "
                 "where the plant can do it\n", words(r.word), words(r.twin), r.event);
  }
  return r.observable ? 0 : 1;
}

int run_project(const Options& o) {
  // Without -o the observer itself goes to standard output: a summary there too would mix them.
  if (o.json && o.out.empty()) throw InputError("--json", "goes with -o FILE (without it the observer is printed instead)");
  const engines::Engine engine = engines::engine_named(o.engine);
  const sv::Automaton a = sv::read_fsm_file(o.file);
  const auto budgeted = [&](const auto& construct) {
    try {
      return construct();
    } catch (const BudgetExceeded& e) {   // the library names the construction; the user knows the file
      throw BudgetExceeded(o.file, std::string(e.what()).substr(e.where().size() + 2));
    }
  };
  // The library's engine writes its compact observer as it is (write_fsm_compact: the bytes of
  // write_fsm(decompile(f))): an observer of 4 M classes decompiled into maps of strings took
  // 4.5 GB under --memory-limit 2G, twice what the budgeted construction needed.
  std::size_t states = 0, transitions = 0;
  if (engine == engines::Engine::impl) {
    WorkBudget work = o.budgets.work();
    const is::Fsm compact = is::compile(a);
    const is::Fsm obs = is::observer(compact, work,
                                     fsm_peaks::project_command(fsm_peaks::bytes_of(compact), compact.event_count()), o.file);
    report_memory(o.budgets, work.peak_estimate());
    if (o.out.empty()) {
      is::write_fsm_compact(std::cout, obs, is::name_speller(obs));
      return 0;
    }
    is::write_fsm_compact_file(o.out, obs, is::name_speller(obs));
    states = obs.state_count();
    transitions = obs.edge_count();
  } else {
    const sv::Automaton obs = budgeted([&] { return engines::observer(a, engine, o.budgets.memory_bytes); });
    if (o.out.empty()) {
      fmt::print("{}", sv::write_fsm(obs));
      return 0;
    }
    sv::write_fsm_file(o.out, obs);
    states = obs.states.size();
    transitions = sv::transition_count(obs);
  }
  const auto erased = sv::unobservable_events(a.events);
  if (o.json)
    print_json(Json{{"input", o.file},
                    {"output", o.out},
                    {"input_states", a.states.size()},
                    {"states", states},
                    {"transitions", transitions},
                    {"erased_events", erased}});
  else
    fmt::print("{}: observer of {} states, {} transitions ({} states in, erased: {})\n", o.out, states, transitions,
               a.states.size(), erased.empty() ? "none" : fmt::format("{}", fmt::join(erased, " ")));
  return 0;
}

}  // namespace fsm_control

void add_fsm_control_subcommands(CLI::App* fsm, int& exit_code) {
  auto o = std::make_shared<fsm_control::Options>();
  auto* ctl = fsm->add_subcommand(
      "controllable",
      "is a given supervisor controllable for the plant, and the closed loop nonblocking? with "
      "shortest witnesses (exit 1 if not)");
  ctl->add_option("--plant", o->plants, "plant component .fsm files")->required()->expected(1, -1);
  ctl->add_option("--sup", o->sup, "the supervisor .fsm")->required();
  ctl->add_flag("--json", o->json, "print JSON");
  ctl->add_option("--engine", o->engine, "impl (fast, default) or model (the reference)")
      ->check(CLI::IsMember({"impl", "model"}));
  add_budget_options(ctl, o->budgets, false);
  add_time_limit_option(ctl, o->budgets);
  ctl->callback([&exit_code, o] {
    exit_code = guarded([&] { return fsm_control::run_controllable(*o); });
  });

  auto* obs = fsm->add_subcommand(
      "observable", "is a specification observable for the plant under its uo events? with a "
                    "witness of two words that look alike (exit 1 if not)");
  obs->add_option("--plant", o->plants, "plant component .fsm files")->required()->expected(1, -1);
  obs->add_option("--spec", o->specs, "specification .fsm files")->required()->expected(1, -1);
  obs->add_flag("--json", o->json, "print JSON");
  obs->add_option("--engine", o->engine, "impl (fast, default) or model (the reference)")
      ->check(CLI::IsMember({"impl", "model"}));
  add_budget_options(obs, o->budgets, false);
  add_time_limit_option(obs, o->budgets);
  obs->callback([&exit_code, o] {
    exit_code = guarded([&] { return fsm_control::run_observable(*o); });
  });

  auto* proj = fsm->add_subcommand(
      "project", "the observer: natural projection onto the observable events, determinised");
  proj->add_option("file", o->file, "the .fsm file")->required();
  proj->add_option("-o,--output", o->out, "the observer .fsm to write (default: standard output)");
  proj->add_flag("--json", o->json, "with -o: print a JSON summary");
  add_budget_options(proj, o->budgets, false);
  add_time_limit_option(proj, o->budgets);
  proj->add_option("--engine", o->engine, "impl (fast, default) or model (the reference)")
      ->check(CLI::IsMember({"impl", "model"}));
  proj->callback([&exit_code, o] {
    exit_code = guarded([&] {
      impl::io::refuse_output_that_is_an_input(o->out, {o->file});
      return fsm_control::run_project(*o);
    });
  });
}

}  // namespace swarmcheck::cli
