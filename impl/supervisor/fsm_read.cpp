// The `.fsm` reader: text -> checks -> the compact automaton (Fsm), and from it the Automaton value.
// Two passes over the text, neither storing tokens: the first finds the byte-level errors (control
// characters, names that are not UTF-8) anywhere in the file, as they come first whatever the
// structure; the second reads line by line, naming states and events by integer ids through hash
// tables of views into the text, so reading is O(size of the text) in time and the result is
// the only large allocation. Structural errors are reported where they are met; undefined
// targets (which may be defined later) once all blocks are read, the first in reading order.
#include <algorithm>
#include <numeric>
#include <optional>
#include <sstream>
#include <string_view>
#include <vector>

#include "impl/supervisor/fsm_compact_io.hpp"
#include "impl/supervisor/fsm_io.hpp"
#include "spec/util/input_error.hpp"
#include "spec/util/input_file.hpp"
#include "spec/util/utf8.hpp"

namespace swarmcheck::impl::supervisor {

namespace {

struct Token {
  std::string_view text;
  std::size_t line = 0;
  std::size_t col = 0;
};
using Line = std::vector<Token>;  // the tokens of one non-blank line

struct Place {
  std::size_t line = 0, col = 0;
};

// What a file says about one event: each attribute with the place it was first stated.
struct EventFacts {
  std::string_view name;
  std::optional<bool> controllable, observable;
  Place controllable_at, observable_at;
};

// A transition kept in its block, by first-appearance ids (renumbered when the file is read).
struct Edge {
  std::uint32_t event, target;   // event id, name id
};

// A target named before any block of that name: an error at the end unless a block follows.
struct Forward {
  std::uint32_t name;
  Place at;
  StateId from;
};

std::string plural(std::size_t n, const std::string& word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

bool is_separator(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::string str(std::string_view s) { return std::string(s); }

// Distinct names (views into the text) numbered in order of first appearance: open addressing
// whose slots hold the id and the hash's high half, so a lookup allocates nothing (a node-based
// map allocates on every emplace, and that was most of the reading time) and a probe compares
// text only when the hashes agree.
class NameTable {
 public:
  std::size_t size() const { return names_.size(); }
  std::string_view operator[](std::uint32_t id) const { return names_[id]; }

  // The id of `name`, and whether it is new.
  std::pair<std::uint32_t, bool> intern(std::string_view name) {
    if (2 * (names_.size() + 1) > slots_.size()) grow();
    const std::uint64_t h = std::hash<std::string_view>{}(name);
    const auto tag = static_cast<std::uint32_t>(h >> 32);
    const std::size_t mask = slots_.size() - 1;
    std::size_t i = h & mask;
    for (; slots_[i].id != kNone; i = (i + 1) & mask)
      if (slots_[i].tag == tag && names_[slots_[i].id] == name) return {slots_[i].id, false};
    const auto id = static_cast<std::uint32_t>(names_.size());
    slots_[i] = {id, tag};
    names_.push_back(name);
    homes_.push_back(h);
    return {id, true};
  }

 private:
  static constexpr std::uint32_t kNone = UINT32_MAX;
  struct Slot {
    std::uint32_t id = kNone, tag = 0;
  };
  void grow() {
    slots_.assign(std::max<std::size_t>(64, 2 * slots_.size()), Slot{});
    const std::size_t mask = slots_.size() - 1;
    for (std::uint32_t id = 0; id < names_.size(); ++id) {
      std::size_t i = homes_[id] & mask;
      while (slots_[i].id != kNone) i = (i + 1) & mask;
      slots_[i] = {id, static_cast<std::uint32_t>(homes_[id] >> 32)};
    }
  }
  std::vector<std::string_view> names_;
  std::vector<std::uint64_t> homes_;  // [id]: the full hash, to place the id again on growth
  std::vector<Slot> slots_;           // power-of-two size, at most half full
};

class Reader {
 public:
  Reader(std::string_view text, std::string source) : text_(text), source_(std::move(source)) {
    check_bytes();
  }

  Fsm read(swarmcheck::supervisor::Statements* stated) {
    const std::size_t n = read_count();
    for (std::size_t i = 0; i < n; ++i) read_block(i, n);
    read_trailer(n);
    check_targets();
    if (stated) *stated = statements();
    return build();
  }

 private:
  [[noreturn]] void fail(std::size_t line, std::size_t col, const std::string& what) const {
    throw InputError(source_ + ":" + std::to_string(line) + ":" + std::to_string(col), what);
  }
  [[noreturn]] void fail(const Token& t, const std::string& what) const {
    fail(t.line, t.col, what);
  }
  [[noreturn]] void fail_eof(const std::string& what) const { fail(eof_line_, eof_col_, what); }

  // Pass 1: the byte-level errors, in the order a tokenizer meets them, and the end's place.
  void check_bytes() {
    std::size_t line = 1, col = 1, word_begin = 0, word_col = 0;
    bool in_word = false;
    auto end_word = [&](std::size_t end) {
      if (!in_word) return;
      in_word = false;
      // Names go into JSON (--json, export): they must be text. The bytes are not echoed.
      const std::string_view word = text_.substr(word_begin, end - word_begin);
      if (const std::size_t bad = utf8::first_invalid_byte(word); bad != std::string_view::npos)
        fail(line, word_col + bad, "a name that is not valid UTF-8 text (byte " +
                                       std::to_string(static_cast<unsigned char>(word[bad])) + ")");
    };
    for (std::size_t i = 0; i < text_.size(); ++i) {
      const char c = text_[i];
      if (c == '\n') {
        end_word(i);
        ++line;
        col = 1;
        continue;
      }
      const auto u = static_cast<unsigned char>(c);
      if (is_separator(c)) {
        end_word(i);
      } else if (u < 0x20 || u == 0x7f) {
        fail(line, col, "unexpected control character (byte " + std::to_string(u) + ")");
      } else if (!in_word) {
        in_word = true;
        word_begin = i;
        word_col = col;
      }
      ++col;
    }
    end_word(text_.size());
    eof_line_ = line;
    eof_col_ = col;
  }

  // Pass 2: the next non-blank line's tokens (views into the text), or null at the end.
  const Line* next_line() {
    while (at_ < text_.size()) {
      line_.clear();
      std::size_t col = 1;
      for (; at_ < text_.size() && text_[at_] != '\n'; ++col) {
        if (is_separator(text_[at_])) {
          ++at_;
          continue;
        }
        const std::size_t begin = at_;
        while (at_ < text_.size() && text_[at_] != '\n' && !is_separator(text_[at_])) ++at_;
        line_.push_back({text_.substr(begin, at_ - begin), line_no_, col});
        col += at_ - begin - 1;
      }
      ++at_;  // the '\n'
      ++line_no_;
      if (!line_.empty()) return &line_;
    }
    return nullptr;
  }

  static std::optional<std::size_t> parse_count(std::string_view s, std::size_t max) {
    if (s.empty() || s.size() > 12) return std::nullopt;
    std::size_t v = 0;
    for (const char c : s) {
      if (c < '0' || c > '9') return std::nullopt;
      v = v * 10 + static_cast<std::size_t>(c - '0');
    }
    if (v > max) return std::nullopt;
    return v;
  }
  static bool is_digits(std::string_view s) {
    return !s.empty() && s.find_first_not_of("0123456789") == std::string_view::npos;
  }
  static bool is_probability(std::string_view s) {
    std::istringstream in{std::string(s)};
    double p = -1;
    in >> p;
    return !in.fail() && in.eof() && p >= 0.0 && p <= 1.0;
  }

  std::size_t read_count() {
    const Line* first = next_line();
    if (!first) fail_eof("empty file: expected the number of states");
    const Line& l = *first;
    const auto n = parse_count(l[0].text, kStatesMax);
    if (!n) {
      if (is_digits(l[0].text))
        fail(l[0], "the number of states " + str(l[0].text) + " is above the limit " +
                       std::to_string(kStatesMax));
      fail(l[0], "expected the number of states (a non-negative integer), got '" + str(l[0].text) +
                     "'");
    }
    if (l.size() > 1)
      fail(l[1], "expected only the number of states on the first line, got '" + str(l[1].text) +
                     "' after it");
    return *n;
  }

  // A line of exactly `name 0|1 count`: what a block header looks like.
  static bool looks_like_header(const Line& l) {
    return l.size() == 3 && (l[1].text == "0" || l[1].text == "1") && is_digits(l[2].text);
  }

  std::uint32_t name_id(std::string_view name) {
    const auto [id, fresh] = names_.intern(name);
    if (fresh) {
      state_of_name_.push_back(kNoState);
      referenced_.push_back(0);
    }
    return id;
  }

  void read_block(std::size_t index, std::size_t declared) {
    const Line* l = next_line();
    if (!l)
      fail_eof("unexpected end of file: the first line declares " + plural(declared, "state") +
               ", but only " + plural(index, "state block") + " follow");
    const Line& h = *l;
    if (h.size() != 3) {
      if (index > 0 && h.size() >= 2 && h.size() <= 5 && !looks_like_header(h))
        fail(h[0], "expected a state block 'name marked count', got a line of " +
                       std::to_string(h.size()) + " fields: does state '" +
                       str(names_[state_names_.back()]) + "' have more transitions than the " +
                       std::to_string(last_declared_) + " it declares?");
      fail(h[0], "expected a state block 'name marked count' (3 fields), got " +
                     std::to_string(h.size()) + " field" + (h.size() == 1 ? "" : "s"));
    }
    const Token name = h[0];
    const std::uint32_t id = name_id(name.text);
    if (state_of_name_[id] != kNoState)
      fail(name, "duplicate state '" + str(name.text) + "' (its first block is at line " +
                     std::to_string(header_line_[state_of_name_[id]]) + ")");
    if (h[1].text != "0" && h[1].text != "1")
      fail(h[1], "expected the marked flag 0 or 1 of state '" + str(name.text) + "', got '" +
                     str(h[1].text) + "'");
    const auto count = parse_count(h[2].text, kTransitionsPerStateMax);
    if (!count)
      fail(h[2], "expected the number of transitions of state '" + str(name.text) +
                     "' (an integer from 0 to " + std::to_string(kTransitionsPerStateMax) +
                     "), got '" + str(h[2].text) + "'");
    const auto state = static_cast<StateId>(state_names_.size());
    state_of_name_[id] = state;
    state_names_.push_back(id);
    header_line_.push_back(name.line);
    marked_.push_back(h[1].text == "1" ? 1 : 0);
    last_declared_ = *count;
    block_begin_ = edges_.size();
    for (std::size_t j = 0; j < *count; ++j) read_transition(name, state, j, *count);
    first_edge_.push_back(edges_.size());
  }

  void read_transition(const Token& state, StateId from, std::size_t index, std::size_t declared) {
    auto promise = [&] {
      return "state '" + str(state.text) + "' declares " + plural(declared, "transition") + " but ";
    };
    const Line* l = next_line();
    if (!l)
      fail_eof("unexpected end of file: " + promise() + "only " + std::to_string(index) +
               " follow");
    const Line& t = *l;
    if (looks_like_header(t))
      fail(t[0], promise() + "only " + std::to_string(index) + " follow before the block of '" +
                     str(t[0].text) + "'");
    if (t.size() < 2)
      fail(t[0], "expected a transition 'event target c|uc o|uo' of state '" + str(state.text) +
                     "', got only '" + str(t[0].text) + "'");
    const std::uint32_t event = event_id(t[0].text);
    if (t.size() >= 3) state_attr(event, t[2], true);
    if (t.size() >= 4) state_attr(event, t[3], false);
    if (t.size() >= 5 && !is_probability(t[4].text))
      fail(t[4], "expected the end of the line (or a probability from 0 to 1) after the "
                 "attributes, got '" + str(t[4].text) + "'");
    if (t.size() >= 6) fail(t[5], "expected the end of the line, got '" + str(t[5].text) + "'");
    const Token target = t[1];
    const std::uint32_t target_id = name_id(target.text);
    // The event's earlier transition in this block, if any: found through the event's last
    // block (an O(1) stamp) instead of a scan of the block.
    if (event_block_[event] == state_names_.size()) {
      const std::size_t k = event_edge_[event];
      if (edges_[k].target == target_id) return;  // a repeated line: same meaning, dropped
      fail(target, "nondeterministic state '" + str(state.text) + "': event '" + str(t[0].text) +
                       "' leads to '" + str(names_[edges_[k].target]) + "' (line " +
                       std::to_string(edge_line_[k - block_begin_]) + ") and to '" +
                       str(target.text) + "'");
    }
    event_block_[event] = state_names_.size();
    event_edge_[event] = edges_.size();
    if (edge_line_.size() <= edges_.size() - block_begin_) edge_line_.resize(edges_.size() - block_begin_ + 1);
    edge_line_[edges_.size() - block_begin_] = t[0].line;
    edges_.push_back({event, target_id});
    if (state_of_name_[target_id] == kNoState && !referenced_[target_id]) {
      referenced_[target_id] = 1;
      forwards_.push_back({target_id, {target.line, target.col}, from});
    }
  }

  std::uint32_t event_id(std::string_view e) {
    const auto [id, fresh] = event_names_.intern(e);
    if (fresh) {
      events_.push_back({e, std::nullopt, std::nullopt, {}, {}});
      event_block_.push_back(SIZE_MAX);
      event_edge_.push_back(0);
    }
    return id;
  }

  // Records `c|uc` (controllability) or `o|uo` for event e; a contradiction is an error here.
  void state_attr(std::uint32_t e, const Token& t, bool controllability) {
    const char* yes = controllability ? "c" : "o";
    const char* no = controllability ? "uc" : "uo";
    EventFacts& f = events_[e];
    if (t.text != yes && t.text != no)
      fail(t, std::string("expected ") + yes + " or " + no + " (" +
                  (controllability ? "controllable or not" : "observable or not") +
                  ") for event '" + str(f.name) + "', got '" + str(t.text) + "'");
    auto& value = controllability ? f.controllable : f.observable;
    auto& at = controllability ? f.controllable_at : f.observable_at;
    const bool v = t.text == yes;
    if (value && *value != v)
      fail(t, "event '" + str(f.name) + "' is " + str(t.text) + " here but " + (*value ? yes : no) +
                  " at line " + std::to_string(at.line) + ":" + std::to_string(at.col));
    if (!value) {
      value = v;
      at = {t.line, t.col};
    }
  }

  void read_trailer(std::size_t declared) {
    const Line* l = next_line();
    if (!l) return;
    if ((*l)[0].text != "EVENTS")
      fail((*l)[0], "the first line declares " + plural(declared, "state") +
                        ", but more text follows: expected the end of the file or an "
                        "EVENTS section, got '" + str((*l)[0].text) + "'");
    if (l->size() > 1) fail((*l)[1], "expected nothing after EVENTS on its line");
    while ((l = next_line())) {
      const Line& t = *l;
      if (t.size() > 3) fail(t[3], "expected 'event c|uc o|uo' in the EVENTS section");
      const std::uint32_t event = event_id(t[0].text);
      if (t.size() >= 2) state_attr(event, t[1], true);
      if (t.size() >= 3) state_attr(event, t[2], false);
    }
  }

  void check_targets() const {
    for (const Forward& f : forwards_)
      if (state_of_name_[f.name] == kNoState)
        fail(f.at.line, f.at.col, "transition target '" + str(names_[f.name]) + "' of state '" +
                                      str(names_[state_names_[f.from]]) +
                                      "' is not a state (no block of that name in this file)");
  }

  // Each event's attributes as this file states them, with the place of the first statement.
  swarmcheck::supervisor::Statements statements() const {
    swarmcheck::supervisor::Statements out;
    auto where = [&](const Place& p) {
      return source_ + ":" + std::to_string(p.line) + ":" + std::to_string(p.col);
    };
    for (const EventFacts& e : events_) {
      auto& st = out[str(e.name)];
      if (e.controllable) st.controllable = {*e.controllable, where(e.controllable_at)};
      if (e.observable) st.observable = {*e.observable, where(e.observable_at)};
    }
    return out;
  }

  // Events renumbered in name order, targets by state, each state's edges sorted by event.
  Fsm build() const {
    Fsm f;
    std::vector<std::uint32_t> by_name(events_.size());
    std::iota(by_name.begin(), by_name.end(), 0);
    std::sort(by_name.begin(), by_name.end(),
              [&](std::uint32_t x, std::uint32_t y) { return events_[x].name < events_[y].name; });
    std::vector<EventId> renumber(events_.size());
    for (std::uint32_t i = 0; i < by_name.size(); ++i) {
      const EventFacts& e = events_[by_name[i]];
      renumber[by_name[i]] = i;
      f.event_names.emplace_back(e.name);
      f.controllable.push_back(e.controllable.value_or(true) ? 1 : 0);
      f.observable.push_back(e.observable.value_or(true) ? 1 : 0);
    }
    f.state_names.reserve(state_names_.size());
    for (const std::uint32_t id : state_names_) f.state_names.emplace_back(names_[id]);
    f.marked = marked_;
    f.first_edge.assign(first_edge_.begin(), first_edge_.end());
    std::vector<std::pair<EventId, StateId>> row;
    f.edge_event.reserve(edges_.size());
    f.edge_target.reserve(edges_.size());
    for (std::size_t s = 0; s + 1 < first_edge_.size(); ++s) {
      row.clear();
      for (std::size_t i = first_edge_[s]; i < first_edge_[s + 1]; ++i)
        row.emplace_back(renumber[edges_[i].event], state_of_name_[edges_[i].target]);
      std::sort(row.begin(), row.end());
      for (const auto& [e, t] : row) {
        f.edge_event.push_back(e);
        f.edge_target.push_back(t);
      }
    }
    return f;
  }

  std::string_view text_;
  std::string source_;
  std::size_t eof_line_ = 1, eof_col_ = 1;
  std::size_t at_ = 0, line_no_ = 1;                       // pass 2's position
  Line line_;                                              // the current line's tokens
  NameTable names_;                                        // state names, of blocks or targets
  std::vector<StateId> state_of_name_;                     // [name id]: its block's state, or none
  std::vector<std::uint8_t> referenced_;                   // [name id]: a forward target already
  std::vector<std::uint32_t> state_names_;                 // [state]: its name id
  std::vector<std::size_t> header_line_;                   // [state]
  std::vector<std::uint8_t> marked_;                       // [state]
  std::vector<std::size_t> first_edge_{0};                 // [state + 1] into edges_
  std::vector<Edge> edges_;                                // kept transitions, block by block
  std::vector<std::size_t> edge_line_;                     // [edge of the current block]: its line
  std::size_t block_begin_ = 0, last_declared_ = 0;
  NameTable event_names_;
  std::vector<EventFacts> events_;                         // [event id], first appearance order
  std::vector<std::size_t> event_block_;                   // [event id]: 1 + its last block's state
  std::vector<std::size_t> event_edge_;                    // [event id]: its edge in that block
  std::vector<Forward> forwards_;
};

}  // namespace

Fsm read_fsm_compact(std::string_view text, const std::string& source,
                     swarmcheck::supervisor::Statements* stated) {
  text.remove_prefix(utf8::byte_order_mark_size(text));   // as JSON inputs allow
  return Reader(text, source).read(stated);
}

Fsm read_fsm_compact_file(const std::string& path, swarmcheck::supervisor::Statements* stated) {
  const std::string text = io_input::read_input_file(path, ".fsm file");
  return read_fsm_compact(text, path, stated);
}

std::vector<Fsm> read_fsm_compact_files(const std::vector<std::string>& paths) {
  std::vector<Fsm> out;
  std::vector<swarmcheck::supervisor::Statements> stated(paths.size());
  for (std::size_t i = 0; i < paths.size(); ++i)
    out.push_back(read_fsm_compact_file(paths[i], &stated[i]));
  const auto attrs = swarmcheck::supervisor::resolve_attributes(stated);
  for (Fsm& f : out)
    for (EventId e = 0; e < f.event_count(); ++e) {
      const auto& a = attrs.at(f.event_names[e]);
      f.controllable[e] = a.controllable ? 1 : 0;
      f.observable[e] = a.observable ? 1 : 0;
    }
  return out;
}

}  // namespace swarmcheck::impl::supervisor

namespace swarmcheck::supervisor {

Automaton read_fsm(std::string_view text, const std::string& source) {
  return impl::supervisor::decompile(impl::supervisor::read_fsm_compact(text, source));
}

Automaton read_fsm_file(const std::string& path) {
  return impl::supervisor::decompile(impl::supervisor::read_fsm_compact_file(path));
}

std::vector<Automaton> read_fsm_files(const std::vector<std::string>& paths) {
  std::vector<Automaton> out;
  for (const auto& f : impl::supervisor::read_fsm_compact_files(paths))
    out.push_back(impl::supervisor::decompile(f));
  return out;
}

}  // namespace swarmcheck::supervisor
