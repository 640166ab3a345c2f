// The `.fsm` writer on the compact automaton (precise form, see fsm_io.hpp): one reused buffer,
// flushed to the stream every megabyte, so writing costs no memory per state.
#include <sstream>

#include "impl/io/atomic_file.hpp"
#include "impl/supervisor/fsm_compact_io.hpp"

namespace swarmcheck::impl::supervisor {

namespace {

constexpr std::size_t kFlushBytes = 1 << 20;

void append_attrs(const Fsm& f, EventId e, std::string& out) {
  out += f.controllable[e] ? "c\t" : "uc\t";
  out += f.observable[e] ? "o" : "uo";
}

}  // namespace

void write_fsm_compact(std::ostream& out, const Fsm& f, const AppendName& name) {
  std::string buf = std::to_string(f.state_count()) + "\n\n";
  std::vector<std::uint8_t> used(f.event_count(), 0);
  for (StateId s = 0; s < f.state_count(); ++s) {
    name(s, buf);
    buf += f.marked[s] ? "\t1\t" : "\t0\t";
    buf += std::to_string(f.first_edge[s + 1] - f.first_edge[s]);
    buf += '\n';
    for (auto i = f.first_edge[s]; i < f.first_edge[s + 1]; ++i) {  // ascending ids: name order
      const EventId e = f.edge_event[i];
      used[e] = 1;
      (buf += f.event_names[e]) += '\t';
      name(f.edge_target[i], buf);
      buf += '\t';
      append_attrs(f, e, buf);
      buf += '\n';
    }
    buf += '\n';
    if (buf.size() >= kFlushBytes) {
      out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
      buf.clear();
    }
  }
  bool header = false;
  for (EventId e = 0; e < f.event_count(); ++e) {
    if (used[e]) continue;
    if (!header) buf += "EVENTS\n";
    header = true;
    (buf += f.event_names[e]) += '\t';
    append_attrs(f, e, buf);
    buf += '\n';
  }
  out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
}

std::string write_fsm_compact(const Fsm& f, const AppendName& name) {
  std::ostringstream out;
  write_fsm_compact(out, f, name);
  return out.str();
}

void write_fsm_compact_file(const std::string& path, const Fsm& f, const AppendName& name) {
  io::AtomicFile file(path);
  write_fsm_compact(file.stream(), f, name);
  file.commit();
}

}  // namespace swarmcheck::impl::supervisor
