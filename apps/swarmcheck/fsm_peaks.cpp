#include "apps/swarmcheck/fsm_peaks.hpp"

namespace swarmcheck::cli::fsm_peaks {

using impl::supervisor::Fsm;
using impl::supervisor::NormalPeaks;
using impl::supervisor::PeakModel;

namespace {

template <class T>
double vector_bytes(const std::vector<T>& v) {
  return static_cast<double>(v.capacity() * sizeof(T));
}

}  // namespace

double bytes_of(const Fsm& f) {
  double b = vector_bytes(f.marked) + vector_bytes(f.controllable) + vector_bytes(f.observable) + vector_bytes(f.first_edge) +
             vector_bytes(f.edge_event) + vector_bytes(f.edge_target) + vector_bytes(f.state_names) + vector_bytes(f.event_names);
  for (const auto& s : f.state_names) b += s.capacity() > 15 ? static_cast<double>(s.capacity() + 1) : 0.0;
  for (const auto& s : f.event_names) b += s.capacity() > 15 ? static_cast<double>(s.capacity() + 1) : 0.0;
  return b;
}

double bytes_of(const std::vector<Fsm>& fs) {
  double b = 0;
  for (const auto& f : fs) b += bytes_of(f);
  return b;
}

// The product's own structures: per state its tuple (4 bytes a part), marking and first edge in
// vectors that double; per transition its event and target; the tuple table's slots. Measured
// (fsm product of two counters, 1 to 9 x 10^6 states): 0.89-1.08x of the peak.
PeakModel product_command(std::size_t parts, double inputs_bytes, bool named) {
  return PeakModel{.fixed = kProcessBytes + inputs_bytes,
                   .per_state = named ? 40.0 : 0.0,   // a name each (std::string), when stored
                   .grown_per_state = 4.0 * static_cast<double>(parts) + 5.0,
                   .grown_per_transition = 8.0,
                   .table_slot_bytes = 4.0};
}

// Synthesis holds the product, its reverse edges (all, and the plant's uncontrollable ones), the
// marks of the fixpoint, and two restrictions of the product with their maps back. Measured
// (transfer lines of 0.08 to 1.3 x 10^6 closed-loop states, 3.5 transitions a state): 0.94-1.0x.
PeakModel synth_command(double inputs_bytes) {
  return PeakModel{.fixed = kProcessBytes + inputs_bytes, .per_state = 60.0, .per_transition = 28.0};
}

// Normal synthesis: the product; its observer's classes (no names); then H, the (state, class)
// pairs, with an edge list and a name each, its reverse edges and the restrictions. Measured
// (counters x (c) and y (uc, uo), 0.3 to 1.5 x 10^6 states): 0.97-1.03x.
NormalPeaks normal_synth_command(double inputs_bytes, std::size_t events) {
  NormalPeaks p;
  p.product = product_command(2, inputs_bytes, false);
  p.observer = PeakModel{.per_state = 49.0 + 4.0 * static_cast<double>(events), .per_transition = 24.0, .grown_per_state = 48.0};
  p.pairs = PeakModel{.per_state = 330.0, .per_transition = 30.0};
  return p;
}

// The observer's classes (their members, their rows of successors, the index), then the observer
// itself with a name per class. Measured (2^16 to 2^20 classes of 10 to 12 members): 0.97-1.02x.
PeakModel project_command(double inputs_bytes, std::size_t events) {
  return PeakModel{.fixed = kProcessBytes + inputs_bytes,
                   .per_state = 49.0 + 4.0 * static_cast<double>(events),
                   .per_transition = 24.0,
                   .grown_per_state = 48.0};
}

PeakModel observable_product(double inputs_bytes) { return product_command(2, inputs_bytes, false); }

// A pair: its node (two states, parent, event) in a vector that doubles, and its index entry
// (a node of the hash map, and its bucket in an array that doubles too). Measured (chains of 300
// to 1 000 states, n^2 pairs): 0.99-1.05x.
PeakModel observable_pairs() { return PeakModel{.per_state = 40.0, .grown_per_state = 24.0}; }

// The closed loop and its checks (violations, reverse edges, coaccessibility, witnesses).
// Measured (counters, 1 to 4 x 10^6 closed-loop states): 0.98-1.13x.
PeakModel controllable_command(double inputs_bytes) {
  return PeakModel{.fixed = kProcessBytes + inputs_bytes, .per_state = 40.0, .per_transition = 20.0};
}

// A pair of the comparison, as observable_pairs. Measured (counters of 1999 and 2001, 2999 and
// 3001 states: 4 and 9 x 10^6 pairs): 1.03-1.08x.
PeakModel compare_pairs(double inputs_bytes) {
  return PeakModel{.fixed = kProcessBytes + inputs_bytes, .per_state = 40.0, .grown_per_state = 24.0};
}

}  // namespace swarmcheck::cli::fsm_peaks
