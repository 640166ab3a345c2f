// swarmcheck.Automaton and the supervisor operations (the library's value API,
// swarmcheck/supervisor.hpp): each result the automaton the CLI writes, each report the dict its
// --json prints (without the file names), witnesses as lists of event names.
#include <pybind11/stl.h>

#include <set>

#include "impl/supervisor/fsm.hpp"
#include "impl/supervisor/operations.hpp"
#include "python/src/bindings.hpp"
#include "python/src/interrupt.hpp"
#include "python/src/json_convert.hpp"
#include "swarmcheck/supervisor.hpp"
#include "views/fsm_svg.hpp"

namespace py = pybind11;
namespace sv = swarmcheck::supervisor;
namespace is = swarmcheck::impl::supervisor;
using sv::Automaton;

namespace swarmcheck::python {
namespace {

// The library's budgeted constructions (the CLI's, without limits), the GIL released: Ctrl-C
// stops one at its next budget check (every 4 096 states of a product or synthesis, 256 classes
// of an observer, 4 096 pairs of a comparison) with KeyboardInterrupt.
template <class F>
auto budgeted(F&& f) {
  return without_gil(
      [&](SignalPoll& poll) {
        WorkBudget budget;
        budget.set_interrupt([&poll] { poll(); });
        return f(budget);
      },
      1);
}

Automaton product_of(const std::vector<Automaton>& parts, std::vector<std::string> names) {
  if (parts.empty()) throw InputError("product", "expected at least one automaton");
  for (std::size_t i = names.size(); i < parts.size(); ++i) names.push_back("part " + std::to_string(i + 1));
  return budgeted([&](WorkBudget& budget) {
    std::vector<is::Fsm> compiled;
    compiled.reserve(parts.size());
    for (const auto& a : parts) compiled.push_back(is::compile(a));
    std::vector<const is::Fsm*> ptrs;
    for (const auto& f : compiled) ptrs.push_back(&f);
    return is::decompile(is::product(ptrs, names, budget, is::PeakModel{}));
  });
}

Automaton supcon_of(const Automaton& plant, const Automaton& spec) {
  return budgeted([&](WorkBudget& budget) {
    const is::Fsm p = is::compile(plant), q = is::compile(spec);   // the synthesis's names borrow them
    is::Synthesis s = is::synthesize(p, q, budget, is::PeakModel{0, 208.0, 16.0});
    is::store_names(s.supervisor, s.names);
    return is::decompile(s.supervisor);
  });
}

Automaton supcon_normal_of(const Automaton& plant, const Automaton& spec) {
  return budgeted([&](WorkBudget& budget) {
    const is::Fsm p = is::compile(plant), q = is::compile(spec);
    return is::decompile(is::supcon_normal(p, q, budget, is::NormalPeaks{}));
  });
}

py::object witness_or_none(bool ok, const std::vector<std::string>& w) {
  return ok ? py::object(py::none()) : py::object(py::cast(w));
}

py::dict check_dict(const Automaton& a) {
  sv::CheckReport r;
  {
    py::gil_scoped_release release;
    r = sv::check(a);
  }
  std::size_t controllable = 0;
  for (const auto& [e, attr] : a.events) controllable += attr.controllable ? 1 : 0;
  py::dict d;
  d["states"] = a.states.size();
  d["initial"] = a.states.empty() ? py::object(py::none()) : py::object(py::str(a.states.front()));
  d["marked"] = a.marked.size();
  d["events"] = a.events.size();
  d["controllable_events"] = controllable;
  d["transitions"] = sv::transition_count(a);
  d["deterministic"] = true;   // the reader refuses nondeterministic files
  d["accessible"] = r.accessible();
  d["unreachable_states"] = r.unreachable_states;
  d["coaccessible"] = r.coaccessible;
  d["nonblocking"] = r.nonblocking();
  d["blocking_states"] = r.blocking_states;
  return d;
}

py::dict inclusion_dict(const sv::Inclusion& i) {
  py::dict d;
  d["closed"] = i.closed;
  d["marked"] = i.marked;
  d["closed_witness"] = witness_or_none(i.closed, i.closed_witness);
  d["marked_witness"] = witness_or_none(i.marked, i.marked_witness);
  return d;
}

// One automaton, or the product of a list (as the CLI's --plant A.fsm B.fsm).
Automaton one_of(const py::handle& h, const char* what) {
  if (py::isinstance<Automaton>(h)) return h.cast<Automaton>();
  if (py::isinstance<py::list>(h) || py::isinstance<py::tuple>(h)) {
    auto parts = h.cast<std::vector<Automaton>>();
    if (parts.empty()) throw InputError(what, "expected at least one automaton");
    if (parts.size() == 1) return parts.front();
    return product_of(parts, {});
  }
  throw py::type_error(std::string(what) + ": expected an Automaton or a list of them");
}

std::vector<std::string> unobservable_of(const Automaton& plant, const Automaton& spec) {
  std::set<std::string> uo;
  for (const Automaton* a : {&plant, &spec})
    for (const auto& e : sv::unobservable_events(a->events)) uo.insert(e);
  return {uo.begin(), uo.end()};
}

py::list transitions_of(const Automaton& a) {
  py::list out;
  for (const auto& q : a.states) {
    const auto it = a.delta.find(q);
    if (it == a.delta.end()) continue;
    for (const auto& [e, to] : it->second) out.append(py::make_tuple(q, e, to));
  }
  return out;
}

}  // namespace

void bind_automata(py::module_& m) {
  py::class_<Automaton>(m, "Automaton", R"(A deterministic automaton of the UMDES .fsm format (a plain value).

Automaton.read(path) and Automaton.parse(text) read .fsm (bad text: swarmcheck.InputError at
file:line:column); write(path) writes it whole or not at all; to_fsm() gives its text.
states[0] is the initial state.)")
      .def(py::init<>(), "The empty automaton.")
      .def_static("read", [](const py::object& path) {
        return sv::read_fsm_file(py::module_::import("os").attr("fspath")(path).cast<std::string>());
      }, py::arg("path"), "Read a .fsm file.")
      .def_static("parse", [](const std::string& text, const std::string& source) { return sv::read_fsm(text, source); },
                  py::arg("text"), py::arg("source") = "<text>", "Read .fsm text; `source` names it in messages.")
      .def("write", [](const Automaton& a, const py::object& path) {
        sv::write_fsm_file(py::module_::import("os").attr("fspath")(path).cast<std::string>(), a);
      }, py::arg("path"), "Write as .fsm, through a temporary file and a rename.")
      .def("to_fsm", &sv::write_fsm, "The .fsm text.")
      .def("to_dot", &sv::to_dot, "Graphviz DOT (marked states doubled, uncontrollable events dashed).")
      .def("to_dict", [](const Automaton& a) { return to_python(json_io::Json::parse(sv::to_json_text(a))); },
           "The JSON of `swarmcheck fsm export --to json`, as a dict.")
      .def("svg", [](const Automaton& a) { return views::fsm_svg(a); },
           "The picture of `swarmcheck fsm export --to svg` (laid out by Graphviz dot).")
      .def("_repr_svg_", [](const Automaton& a) -> py::object {
        // A notebook shows the text form instead when dot is missing or the automaton too big.
        if (!views::dot_available() || sv::transition_count(a) > views::kLayoutTransitionsMax) return py::none();
        return py::str(views::fsm_svg(a));
      })
      .def_property_readonly("states", [](const Automaton& a) { return a.states; }, "State names; states[0] is initial.")
      .def_property_readonly("initial", [](const Automaton& a) -> py::object {
        return a.states.empty() ? py::object(py::none()) : py::object(py::str(a.states.front()));
      }, "The initial state, or None for the empty automaton.")
      .def_property_readonly("marked", [](const Automaton& a) { return a.marked; }, "The marked states (a set).")
      .def_property_readonly("events", [](const Automaton& a) {
        py::dict d;
        for (const auto& [e, attr] : a.events) {
          py::dict at;
          at["controllable"] = attr.controllable;
          at["observable"] = attr.observable;
          d[py::str(e)] = at;
        }
        return d;
      }, "The alphabet: {event: {'controllable': bool, 'observable': bool}}.")
      .def_property_readonly("transitions", &transitions_of, "[(state, event, next state)] in state order.")
      .def("check", &check_dict, "What `swarmcheck fsm check --json` prints (without 'file'): sizes, accessible, "
                                 "unreachable_states, coaccessible, nonblocking, blocking_states.")
      .def("trim", [](const Automaton& a) { py::gil_scoped_release r; return sv::trim(a); }, "The accessible and coaccessible part.")
      .def("accessible_part", [](const Automaton& a) { py::gil_scoped_release r; return sv::accessible_part(a); },
           "The accessible part.")
      .def("observer", [](const Automaton& a) {
        return budgeted([&](WorkBudget& budget) {
          return is::decompile(is::observer(is::compile(a), budget, is::PeakModel{}, "observer"));
        });
      },
           "The observer (`fsm project`): the projection onto the observable events, determinised.")
      .def("__eq__", [](const Automaton& a, const Automaton& b) { return a == b; })
      .def("__len__", [](const Automaton& a) { return a.states.size(); })
      .def("__repr__", [](const Automaton& a) {
        return "<swarmcheck.Automaton: " + std::to_string(a.states.size()) + " states, " + std::to_string(a.events.size()) +
               " events, " + std::to_string(sv::transition_count(a)) + " transitions>";
      });

  m.def("read_fsm_files", [](const std::vector<std::string>& paths) { return sv::read_fsm_files(paths); }, py::arg("paths"),
        "Read the .fsm files of one command together: an attribute (c|uc, o|uo) a file leaves unstated comes from "
        "the files that state it (as the CLI reads --plant and --spec files).");
  m.def("product", &product_of, py::arg("automata"), py::arg("names") = std::vector<std::string>{},
        "The synchronous product (accessible part), states 'x1.x2...', as `swarmcheck fsm product` writes it.");
  m.def("supcon", [](const py::object& plant, const py::object& spec) {
    return supcon_of(one_of(plant, "plant"), one_of(spec, "spec"));
  }, py::arg("plant"), py::arg("spec"), "The supremal controllable nonblocking supervisor (empty when none exists).");
  m.def("supcon_normal", [](const py::object& plant, const py::object& spec) {
    return supcon_normal_of(one_of(plant, "plant"), one_of(spec, "spec"));
  }, py::arg("plant"), py::arg("spec"), "The supremal controllable, normal and nonblocking supervisor (uo events).");
  m.def("synthesize", [](const py::object& plant, const py::object& spec) {
    const Automaton p = one_of(plant, "plant"), s = one_of(spec, "spec");
    return unobservable_of(p, s).empty() ? supcon_of(p, s) : supcon_normal_of(p, s);
  }, py::arg("plant"), py::arg("spec"),
        "`swarmcheck fsm synth`: the product of each list, then supcon, or supcon_normal when an event is uo.");
  m.def("is_controllable", [](const py::object& plant, const py::object& spec) {
    const Automaton p = one_of(plant, "plant"), s = one_of(spec, "spec");
    return budgeted([&](WorkBudget& budget) {
      return is::is_controllable(is::compile(p), is::compile(s), budget, is::PeakModel{});
    });
  }, py::arg("plant"), py::arg("spec"), "Is spec controllable with respect to plant?");
  m.def("control_report", [](const py::object& plant, const py::object& sup) {
    const Automaton p = one_of(plant, "plant"), s = one_of(sup, "sup");
    const sv::ControlReport r = budgeted([&](WorkBudget& budget) {
      return is::control_report(is::compile(p), is::compile(s), budget, is::PeakModel{});
    });
    py::dict d;
    d["plant_states"] = p.states.size();
    d["supervisor_states"] = s.states.size();
    d["closed_loop_states"] = r.closed_loop_states;
    d["controllable"] = r.controllable;
    d["witness"] = witness_or_none(r.controllable, r.witness);
    d["disabled_event"] = r.controllable ? py::object(py::none()) : py::object(py::str(r.disabled_event));
    d["nonblocking"] = r.nonblocking;
    d["blocking_witness"] = witness_or_none(r.nonblocking, r.blocking_witness);
    return d;
  }, py::arg("plant"), py::arg("sup"),
        "`swarmcheck fsm controllable --json` (without the files): is sup controllable for plant, and the closed "
        "loop nonblocking? With shortest witnesses (lists of events).");
  m.def("observability", [](const py::object& plant, const py::object& spec) {
    const Automaton p = one_of(plant, "plant"), s = one_of(spec, "spec");
    const sv::ObservabilityReport r = budgeted([&](WorkBudget& budget) {
      return is::observability(is::compile(p), is::compile(s), budget, is::PeakModel{}, is::PeakModel{});
    });
    py::dict d;
    d["unobservable_events"] = unobservable_of(p, s);
    d["observable"] = r.observable;
    d["word"] = witness_or_none(r.observable, r.word);
    d["twin"] = witness_or_none(r.observable, r.twin);
    d["event"] = r.observable ? py::object(py::none()) : py::object(py::str(r.event));
    return d;
  }, py::arg("plant"), py::arg("spec"),
        "`swarmcheck fsm observable --json` (without the files): with two words that look alike as a witness.");
  m.def("language_inclusion", [](const Automaton& a, const Automaton& b) {
    return inclusion_dict(budgeted([&](WorkBudget& budget) {
      return is::language_inclusion(is::compile(a), is::compile(b), budget, is::PeakModel{});
    }));
  }, py::arg("a"), py::arg("b"), "L(a) in L(b) and Lm(a) in Lm(b), each with its shortlex-least witness.");
  m.def("compare", [](const Automaton& a, const Automaton& b) {
    const auto [ab, ba] = budgeted([&](WorkBudget& budget) {
      const is::Fsm fa = is::compile(a), fb = is::compile(b);
      return std::make_pair(is::language_inclusion(fa, fb, budget, is::PeakModel{}),
                            is::language_inclusion(fb, fa, budget, is::PeakModel{}));
    });
    py::dict d, da, db;
    da["states"] = a.states.size();
    db["states"] = b.states.size();
    d["a"] = da;
    d["b"] = db;
    d["a_in_b"] = inclusion_dict(ab);
    d["b_in_a"] = inclusion_dict(ba);
    return d;
  }, py::arg("a"), py::arg("b"), "`swarmcheck fsm compare --json` (without the files): inclusion both ways.");
}

}  // namespace swarmcheck::python
