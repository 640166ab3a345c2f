// The `.fsm` reader: text -> lines of tokens with positions -> blocks -> checks -> Automaton.
// Structural errors are reported where they are met; cross-references (targets, which may be
// defined later) once all blocks are read, in file order, so the first error in reading order wins.
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <vector>

#include "impl/supervisor/fsm_io.hpp"
#include "spec/util/input_error.hpp"
#include "spec/util/input_file.hpp"
#include "spec/util/utf8.hpp"

namespace swarmcheck::impl::supervisor {

namespace {

using swarmcheck::supervisor::EventAttr;

struct Token {
  std::string text;
  std::size_t line = 0;
  std::size_t col = 0;
};
using Line = std::vector<Token>;  // the tokens of one non-blank line

struct Transition {
  Token event, target;
};

// What a file says about one event: each attribute with the place it was first stated.
struct EventFacts {
  std::optional<bool> controllable, observable;
  Token controllable_at, observable_at;
};

std::string plural(std::size_t n, const std::string& word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

bool is_separator(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

class Reader {
 public:
  Reader(std::string_view text, std::string source) : source_(std::move(source)) {
    tokenize(text);
  }

  Automaton read() {
    const std::size_t n = read_count();
    for (std::size_t i = 0; i < n; ++i) read_block(i, n);
    read_trailer(n);
    check_targets();
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

  void tokenize(std::string_view text) {
    std::size_t line = 1, col = 1;
    Line current;
    std::string word;
    std::size_t word_col = 0;
    auto end_word = [&] {
      // Names go into JSON (--json, export): they must be text. The bytes are not echoed.
      if (const std::size_t bad = utf8::first_invalid_byte(word); bad != std::string_view::npos)
        fail(line, word_col + bad, "a name that is not valid UTF-8 text (byte " +
                                       std::to_string(static_cast<unsigned char>(word[bad])) + ")");
      if (!word.empty()) current.push_back({std::move(word), line, word_col});
      word.clear();
    };
    for (const char c : text) {
      if (c == '\n') {
        end_word();
        if (!current.empty()) lines_.push_back(std::move(current));
        current.clear();
        ++line;
        col = 1;
        continue;
      }
      const auto u = static_cast<unsigned char>(c);
      if (is_separator(c)) {
        end_word();
      } else if (u < 0x20 || u == 0x7f) {
        fail(line, col, "unexpected control character (byte " + std::to_string(u) + ")");
      } else {
        if (word.empty()) word_col = col;
        word += c;
      }
      ++col;
    }
    end_word();
    if (!current.empty()) lines_.push_back(std::move(current));
    eof_line_ = line;
    eof_col_ = col;
  }

  static std::optional<std::size_t> parse_count(const std::string& s, std::size_t max) {
    if (s.empty() || s.size() > 12) return std::nullopt;
    std::size_t v = 0;
    for (const char c : s) {
      if (c < '0' || c > '9') return std::nullopt;
      v = v * 10 + static_cast<std::size_t>(c - '0');
    }
    if (v > max) return std::nullopt;
    return v;
  }
  static bool is_digits(const std::string& s) {
    return !s.empty() && s.find_first_not_of("0123456789") == std::string::npos;
  }
  static bool is_probability(const std::string& s) {
    std::istringstream in(s);
    double p = -1;
    in >> p;
    return !in.fail() && in.eof() && p >= 0.0 && p <= 1.0;
  }

  std::size_t read_count() {
    if (lines_.empty()) fail_eof("empty file: expected the number of states");
    const Line& l = lines_[0];
    const auto n = parse_count(l[0].text, kStatesMax);
    if (!n) {
      if (is_digits(l[0].text))
        fail(l[0], "the number of states " + l[0].text + " is above the limit " +
                       std::to_string(kStatesMax));
      fail(l[0], "expected the number of states (a non-negative integer), got '" + l[0].text +
                     "'");
    }
    if (l.size() > 1)
      fail(l[1], "expected only the number of states on the first line, got '" + l[1].text +
                     "' after it");
    next_ = 1;
    return *n;
  }

  const Line* next_line() { return next_ < lines_.size() ? &lines_[next_++] : nullptr; }

  // A line of exactly `name 0|1 count`: what a block header looks like.
  static bool looks_like_header(const Line& l) {
    return l.size() == 3 && (l[1].text == "0" || l[1].text == "1") && is_digits(l[2].text);
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
                       std::to_string(h.size()) + " fields: does state '" + order_.back().text +
                       "' have more transitions than the " +
                       std::to_string(declared_.at(order_.back().text)) + " it declares?");
      fail(h[0], "expected a state block 'name marked count' (3 fields), got " +
                     std::to_string(h.size()) + " field" + (h.size() == 1 ? "" : "s"));
    }
    const Token& name = h[0];
    const auto dup = header_at_.find(name.text);
    if (dup != header_at_.end())
      fail(name, "duplicate state '" + name.text + "' (its first block is at line " +
                     std::to_string(dup->second.line) + ")");
    if (h[1].text != "0" && h[1].text != "1")
      fail(h[1], "expected the marked flag 0 or 1 of state '" + name.text + "', got '" +
                     h[1].text + "'");
    const auto count = parse_count(h[2].text, kTransitionsPerStateMax);
    if (!count)
      fail(h[2], "expected the number of transitions of state '" + name.text +
                     "' (an integer from 0 to " + std::to_string(kTransitionsPerStateMax) +
                     "), got '" + h[2].text + "'");
    header_at_.emplace(name.text, name);
    declared_.emplace(name.text, *count);
    order_.push_back(name);
    if (h[1].text == "1") marked_.push_back(name.text);
    auto& block = blocks_[name.text];
    for (std::size_t j = 0; j < *count; ++j) read_transition(name, j, *count, block);
  }

  void read_transition(const Token& state, std::size_t index, std::size_t declared,
                       std::vector<Transition>& block) {
    const std::string promise =
        "state '" + state.text + "' declares " + plural(declared, "transition") + " but ";
    const Line* l = next_line();
    if (!l)
      fail_eof("unexpected end of file: " + promise + "only " + std::to_string(index) +
               " follow");
    const Line& t = *l;
    if (looks_like_header(t))
      fail(t[0], promise + "only " + std::to_string(index) + " follow before the block of '" +
                     t[0].text + "'");
    if (t.size() < 2)
      fail(t[0], "expected a transition 'event target c|uc o|uo' of state '" + state.text +
                     "', got only '" + t[0].text + "'");
    if (t.size() >= 3) state_attr(t[0].text, t[2], true);
    if (t.size() >= 4) state_attr(t[0].text, t[3], false);
    if (t.size() >= 5 && !is_probability(t[4].text))
      fail(t[4], "expected the end of the line (or a probability from 0 to 1) after the "
                 "attributes, got '" + t[4].text + "'");
    if (t.size() >= 6) fail(t[5], "expected the end of the line, got '" + t[5].text + "'");
    if (t.size() < 3) note_event(t[0].text);
    for (const auto& earlier : block) {
      if (earlier.event.text != t[0].text) continue;
      if (earlier.target.text == t[1].text) return;  // a repeated line: same meaning, dropped
      fail(t[1], "nondeterministic state '" + state.text + "': event '" + t[0].text +
                     "' leads to '" + earlier.target.text + "' (line " +
                     std::to_string(earlier.event.line) + ") and to '" + t[1].text + "'");
    }
    block.push_back({t[0], t[1]});
  }

  void note_event(const std::string& e) { events_[e]; }

  // Records `c|uc` (controllability) or `o|uo` for event e; a contradiction is an error here.
  void state_attr(const std::string& e, const Token& t, bool controllability) {
    const char* yes = controllability ? "c" : "o";
    const char* no = controllability ? "uc" : "uo";
    if (t.text != yes && t.text != no)
      fail(t, std::string("expected ") + yes + " or " + no + " (" +
                  (controllability ? "controllable or not" : "observable or not") +
                  ") for event '" + e + "', got '" + t.text + "'");
    note_event(e);
    EventFacts& f = events_[e];
    auto& value = controllability ? f.controllable : f.observable;
    auto& at = controllability ? f.controllable_at : f.observable_at;
    const bool v = t.text == yes;
    if (value && *value != v)
      fail(t, "event '" + e + "' is " + t.text + " here but " + (*value ? yes : no) +
                  " at line " + std::to_string(at.line) + ":" + std::to_string(at.col));
    if (!value) {
      value = v;
      at = t;
    }
  }

  void read_trailer(std::size_t declared) {
    const Line* l = next_line();
    if (!l) return;
    if ((*l)[0].text != "EVENTS")
      fail((*l)[0], "the first line declares " + plural(declared, "state") +
                        ", but more text follows: expected the end of the file or an "
                        "EVENTS section, got '" + (*l)[0].text + "'");
    if (l->size() > 1) fail((*l)[1], "expected nothing after EVENTS on its line");
    while ((l = next_line())) {
      const Line& t = *l;
      if (t.size() > 3) fail(t[3], "expected 'event c|uc o|uo' in the EVENTS section");
      note_event(t[0].text);
      if (t.size() >= 2) state_attr(t[0].text, t[1], true);
      if (t.size() >= 3) state_attr(t[0].text, t[2], false);
    }
  }

  void check_targets() const {
    for (const auto& name : order_)
      for (const auto& tr : blocks_.at(name.text))
        if (!header_at_.count(tr.target.text))
          fail(tr.target, "transition target '" + tr.target.text + "' of state '" + name.text +
                              "' is not a state (no block of that name in this file)");
  }

  Automaton build() const {
    Automaton a;
    for (const auto& name : order_) a.states.push_back(name.text);
    a.marked.insert(marked_.begin(), marked_.end());
    for (const auto& [e, f] : events_)
      a.events[e] = EventAttr{f.controllable.value_or(true), f.observable.value_or(true)};
    for (const auto& name : order_) {
      const auto& block = blocks_.at(name.text);
      if (block.empty()) continue;
      auto& row = a.delta[name.text];
      for (const auto& tr : block) row[tr.event.text] = tr.target.text;
    }
    return a;
  }

  std::string source_;
  std::vector<Line> lines_;
  std::size_t next_ = 0;
  std::size_t eof_line_ = 1, eof_col_ = 1;
  std::vector<Token> order_;                              // block headers' names, in order
  std::map<std::string, Token> header_at_;                // state -> its name token
  std::map<std::string, std::vector<Transition>> blocks_;
  std::vector<std::string> marked_;
  std::map<std::string, std::size_t> declared_;          // state -> its transition count
  std::map<std::string, EventFacts> events_;
};

}  // namespace

}  // namespace swarmcheck::impl::supervisor

namespace swarmcheck::supervisor {

Automaton read_fsm(std::string_view text, const std::string& source) {
  return impl::supervisor::Reader(text, source).read();
}

Automaton read_fsm_file(const std::string& path) {
  return read_fsm(io_input::read_input_file(path, ".fsm file"), path);
}

}  // namespace swarmcheck::supervisor
