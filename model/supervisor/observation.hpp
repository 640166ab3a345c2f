#pragma once
// The reference model of partial observation (spec/supervisor/observation.hpp): observer,
// observability check and the supremal controllable normal nonblocking supervisor, each by
// whole-set passes over plain sets of states.
#include "model/supervisor/operations.hpp"
#include "spec/supervisor/observation.hpp"

namespace swarmcheck::model::supervisor {

using swarmcheck::supervisor::ObservabilityReport;

// Obs(a): subset construction over the observable events (names "{q,r}").
Automaton observer(const Automaton& a);

// Is L(plant || spec) observable for plant? With the first violation of the twin search.
ObservabilityReport observability(const Automaton& plant, const Automaton& spec);

// The supremal controllable, normal (for the natural projection) and nonblocking supervisor.
//   A = plant || spec; its observer classes X_0, X_1, ... in the observer's breadth-first order;
//   H = the pairs (z, k) with z in X_k, met breadth first from (z0, 0) with events in name order:
//   (z, k) --e--> (delta_A(z, e), k) for e unobservable, (delta_A(z, e), Obs's k --e--> k') else;
//   named pair_name(z, "o<k>"). H's language is L(A), and the words with one projection w end
//   exactly in the states of one class, so removing a word forces removing its whole class.
//   A class is spoiled when a member z = (x, y) leaks an unobservable event (the plant can do it,
//   spec cannot), or is the e-successor of a class with a member that leaks the observable e.
//   C = the unspoiled classes; repeat: keep the classes of C whose members disable no
//   uncontrollable event of the plant and whose uncontrollable successors' classes are in C, then
//   the classes whose every member reaches a marked state through kept classes; until C is
//   stable. Result: H restricted to the classes of C, accessible part (empty when class 0 goes).
// With no unobservable event it gives the language of supcon (which the command line then uses).
Automaton supcon_normal(const Automaton& plant, const Automaton& spec);

}  // namespace swarmcheck::model::supervisor
