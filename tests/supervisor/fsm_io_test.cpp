// The .fsm reader and writer: every malformed case with its exact message, the liberal forms
// that are accepted, the precise form that is written, and round trips.
#include <gtest/gtest.h>

#include "impl/supervisor/fsm_io.hpp"
#include "spec/util/input_error.hpp"

namespace {

using swarmcheck::InputError;
using swarmcheck::impl::supervisor::read_fsm;
using swarmcheck::impl::supervisor::read_fsm_file;
using swarmcheck::impl::supervisor::write_fsm;
using swarmcheck::supervisor::Automaton;

std::string error_of(const std::string& text) {
  try {
    read_fsm(text, "t.fsm");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(FsmRead, EmptyFile) {
  EXPECT_EQ(error_of(""), "t.fsm:1:1: empty file: expected the number of states");
  EXPECT_EQ(error_of("\n\n  \n"), "t.fsm:4:1: empty file: expected the number of states");
}

// A UTF-8 byte order mark (editors on Windows write one) is skipped, as JSON inputs skip it.
TEST(FsmRead, AByteOrderMarkIsSkippedAndTheAutomatonIsTheSame) {
  const std::string text = "2\n\ns1 0 1\ngo s2 c o\n\ns2 1 0\n";
  EXPECT_EQ(read_fsm("\xEF\xBB\xBF" + text, "t.fsm"), read_fsm(text, "t.fsm"));
  EXPECT_EQ(error_of("\xEF\xBB\xBFx\n"), "t.fsm:1:1: expected the number of states (a non-negative integer), got 'x'");
}

TEST(FsmRead, BadStateCount) {
  EXPECT_EQ(error_of("x\n"),
            "t.fsm:1:1: expected the number of states (a non-negative integer), got 'x'");
  EXPECT_EQ(error_of("-3\n"),
            "t.fsm:1:1: expected the number of states (a non-negative integer), got '-3'");
  EXPECT_EQ(error_of("999999999999\n"),
            "t.fsm:1:1: the number of states 999999999999 is above the limit 100000000");
  EXPECT_EQ(error_of("72 s1 0 2\n"),
            "t.fsm:1:4: expected only the number of states on the first line, got 's1' after it");
}

TEST(FsmRead, CountMismatchFewerBlocks) {
  EXPECT_EQ(error_of("3\ns1 0 0\ns2 0 0\n"),
            "t.fsm:4:1: unexpected end of file: the first line declares 3 states, but only 2 "
            "state blocks follow");
}

TEST(FsmRead, CountMismatchMoreBlocks) {
  EXPECT_EQ(error_of("1\ns1 0 0\n\ns2 0 0\n"),
            "t.fsm:4:1: the first line declares 1 state, but more text follows: expected the "
            "end of the file or an EVENTS section, got 's2'");
}

TEST(FsmRead, TargetNotAState) {
  EXPECT_EQ(error_of("1\ns1 0 1\na s9 c o\n"),
            "t.fsm:3:3: transition target 's9' of state 's1' is not a state (no block of that "
            "name in this file)");
}

TEST(FsmRead, EventControllableInOnePlaceUncontrollableInAnother) {
  EXPECT_EQ(error_of("2\ns1 0 1\na s2 c o\ns2 0 1\na s1 uc o\n"),
            "t.fsm:5:6: event 'a' is uc here but c at line 3:6");
  EXPECT_EQ(error_of("2\ns1 0 1\na s2 c o\ns2 0 1\na s1 c uo\n"),
            "t.fsm:5:8: event 'a' is uo here but o at line 3:8");
}

TEST(FsmRead, DuplicateState) {
  EXPECT_EQ(error_of("2\ns1 0 0\ns1 1 0\n"),
            "t.fsm:3:1: duplicate state 's1' (its first block is at line 2)");
}

TEST(FsmRead, NondeterministicState) {
  EXPECT_EQ(error_of("2\ns1 0 2\na s1 c o\na s2 c o\ns2 0 0\n"),
            "t.fsm:4:3: nondeterministic state 's1': event 'a' leads to 's1' (line 3) and to "
            "'s2'");
}

TEST(FsmRead, TruncatedInsideABlock) {
  EXPECT_EQ(error_of("1\ns1 0 2\na s1 c o\n"),
            "t.fsm:4:1: unexpected end of file: state 's1' declares 2 transitions but only 1 "
            "follow");
  EXPECT_EQ(error_of("1\ns1 0 2\na s1 c o"),  // no final newline: the end is on line 3
            "t.fsm:3:9: unexpected end of file: state 's1' declares 2 transitions but only 1 "
            "follow");
  EXPECT_EQ(error_of("2\ns1 0 2\na s1\ns2 0 0\n"),
            "t.fsm:4:1: state 's1' declares 2 transitions but only 1 follow before the block "
            "of 's2'");
}

TEST(FsmRead, MoreTransitionsThanDeclared) {
  EXPECT_EQ(error_of("2\ns1 0 1\na s2 c o\nb s2 c o\ns2 0 0\n"),
            "t.fsm:4:1: expected a state block 'name marked count', got a line of 4 fields: "
            "does state 's1' have more transitions than the 1 it declares?");
}

TEST(FsmRead, BadTokens) {
  // The thesis's Appendix C prints "s56 O 1" (letter O): exactly the error a user meets.
  EXPECT_EQ(error_of("1\ns56 O 0\n"),
            "t.fsm:2:5: expected the marked flag 0 or 1 of state 's56', got 'O'");
  EXPECT_EQ(error_of("1\ns1 0 two\n"),
            "t.fsm:2:6: expected the number of transitions of state 's1' (an integer from 0 to "
            "1000000), got 'two'");
  EXPECT_EQ(error_of("1\ns1 0 1\na s1 x o\n"),
            "t.fsm:3:6: expected c or uc (controllable or not) for event 'a', got 'x'");
  EXPECT_EQ(error_of("1\ns1 0 1\na s1 c 0\n"),
            "t.fsm:3:8: expected o or uo (observable or not) for event 'a', got '0'");
  EXPECT_EQ(error_of("1\ns1 0 1\na s1 c o zz\n"),
            "t.fsm:3:10: expected the end of the line (or a probability from 0 to 1) after the "
            "attributes, got 'zz'");
  EXPECT_EQ(error_of("1\ns1 0 1\na\n"),
            "t.fsm:3:1: expected a transition 'event target c|uc o|uo' of state 's1', got only "
            "'a'");
  EXPECT_EQ(error_of("1\ns1 0\n"),
            "t.fsm:2:1: expected a state block 'name marked count' (3 fields), got 2 fields");
  EXPECT_EQ(error_of("1\ns\x01 0 0\n"), "t.fsm:2:2: unexpected control character (byte 1)");
  EXPECT_EQ(error_of("1\ns1 0 0\nEVENTS x\n"),
            "t.fsm:3:8: expected nothing after EVENTS on its line");
}

TEST(FsmRead, LiberalForms) {
  // Tabs or spaces, CRLF, blank lines anywhere, attributes left out (c o, or what the same
  // event states elsewhere), a probability field, a repeated identical line, EVENTS section.
  const Automaton a = read_fsm(
      "\n 2 \r\n\n\ns1\t0 4\r\n\na s2\nb s2 uc\n\tb  s2 uc o 0.5\nc s1 c o\n\ns2 1 1\nb s1\n"
      "\nEVENTS\nd uc uo\ne\n",
      "t.fsm");
  EXPECT_EQ(a.states, (std::vector<std::string>{"s1", "s2"}));
  EXPECT_EQ(a.marked, (std::set<std::string>{"s2"}));
  EXPECT_EQ(a.events.size(), 5u);
  EXPECT_TRUE(a.events.at("a").controllable);
  EXPECT_FALSE(a.events.at("b").controllable);  // omitted on line 13, stated uc elsewhere
  EXPECT_FALSE(a.events.at("d").observable);
  EXPECT_TRUE(a.events.at("e").controllable);
  EXPECT_EQ(a.delta.at("s1").size(), 3u);
  EXPECT_EQ(a.delta.at("s2").at("b"), "s1");
}

TEST(FsmWrite, PreciseForm) {
  const Automaton a =
      read_fsm("2\ns1 0 2\nb s2 uc\na s1\ns2 1 0\nEVENTS\nz uc uo\n", "t.fsm");
  EXPECT_EQ(write_fsm(a),
            "2\n\ns1\t0\t2\na\ts1\tc\to\nb\ts2\tuc\to\n\ns2\t1\t0\n\nEVENTS\nz\tuc\tuo\n");
}

TEST(FsmWrite, EmptyAutomaton) {
  const Automaton a = read_fsm("0\n", "t.fsm");
  EXPECT_TRUE(a.states.empty());
  EXPECT_EQ(write_fsm(a), "0\n\n");
}

TEST(FsmRoundTrip, ThesisSupervisor) {
  const Automaton a = read_fsm_file(SWARMCHECK_SCENARIOS "/thesis/control2.fsm");
  EXPECT_EQ(a.states.size(), 72u);
  EXPECT_EQ(a.states.front(), "s1");
  EXPECT_EQ(a.marked, (std::set<std::string>{"s134:146:143"}));
  EXPECT_EQ(read_fsm(write_fsm(a), "again"), a);
}

TEST(FsmRead, MissingFile) {
  EXPECT_THROW(read_fsm_file("/nonexistent/x.fsm"), InputError);
}

}  // namespace
