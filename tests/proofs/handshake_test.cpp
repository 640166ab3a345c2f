// handshake obligations on concrete runs: random arrival sequences through the spec's
// environment_handshake and controller_step never break the protocol under Jacobi, nor the
// epoch handshake under the broken orders; the broken orders are caught by exhaustive search;
// the Z3 encoding computes the same runs; the refuted obligations' traces read back and show.
#include <cstdlib>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "proofs/obligations/handshake_encoding.hpp"
#include "proofs/obligations/handshake_trace.hpp"
#include "proofs/obligations/runner.hpp"
#include "spec/util/input_error.hpp"

namespace swarmcheck::proofs::handshake {
namespace {

// One seed for every run (an RC_PARAMS in the environment wins): CI and a developer see the
// same cases.
const bool kSeededProofsHandshakeTest = [] { return ::setenv("RC_PARAMS", "seed=17", 0) == 0; }();

// A robot on its waypoint (0.5, 0.5) or 3 m along its row, heading 0; waypoints stay put.
std::vector<RobotInput> poses(const std::vector<bool>& arrival) {
  std::vector<RobotInput> in;
  for (bool at : arrival) in.push_back(RobotInput{at ? 0.5 : 3.5, 0.5, 0.0, 0.5, 0.5});
  return in;
}

std::string run_arrivals(const Variant& v, int robots, const std::vector<std::vector<bool>>& seq) {
  ConcreteState s = initial_state(v, robots);
  for (const auto& arrival : seq) {
    const StepEvents ev = step(v, exploration::RobotParams{}, s, poses(arrival));
    if (!ev.violated.empty()) return ev.violated;
  }
  return "";
}

rc::Gen<std::vector<std::vector<bool>>> arrivals(int robots) {
  return rc::gen::container<std::vector<std::vector<bool>>>(
      rc::gen::container<std::vector<bool>>(static_cast<std::size_t>(robots), rc::gen::arbitrary<bool>()));
}

RC_GTEST_PROP(HandshakeProof, JacobiWithTheSpecsControllersKeepsBothPropertiesOnRandomArrivals, ()) {
  const int robots = *rc::gen::inRange(1, 9);
  RC_ASSERT(run_arrivals(Variant{Master::jacobi, Protocol::flag, false}, robots, *arrivals(robots)).empty());
}

RC_GTEST_PROP(HandshakeProof, EpochHandshakeKeepsBothPropertiesUnderGaussSeidelAndLateControllers, ()) {
  const int robots = *rc::gen::inRange(1, 9);
  const Variant v{*rc::gen::element(Master::jacobi, Master::gauss_seidel), Protocol::epoch,
                  *rc::gen::arbitrary<bool>()};
  RC_ASSERT(run_arrivals(v, robots, *arrivals(robots)).empty());
}

// The first property broken by any arrival sequence of at most `depth` steps (two robots).
std::string first_violation(const Variant& v, int depth) {
  for (int len = 1; len <= depth; ++len)
    for (unsigned code = 0; code < (1U << (2 * len)); ++code) {
      std::vector<std::vector<bool>> seq;
      for (int t = 0; t < len; ++t) seq.push_back({((code >> (2 * t)) & 1U) != 0, ((code >> (2 * t + 1)) & 1U) != 0});
      const std::string bad = run_arrivals(v, 2, seq);
      if (!bad.empty()) return bad;
    }
  return "";
}

TEST(HandshakeProof, ConcreteSearchCatchesTheGaussSeidelMasterAndTheLateController) {
  EXPECT_EQ(first_violation(Variant{Master::gauss_seidel, Protocol::flag, false}, 6), "fresh-acceptance");
  EXPECT_EQ(first_violation(Variant{Master::jacobi, Protocol::flag, true}, 6), "no-early-plan");
  EXPECT_EQ(first_violation(Variant{Master::jacobi, Protocol::flag, false}, 6), "");
}

// The Z3 transition system, with the poses and parameters fixed, has exactly the concrete
// run's plans, acceptances and violations.
RC_GTEST_PROP(HandshakeProof, Z3EncodingComputesTheConcreteRun, ()) {
  const int robots = *rc::gen::inRange(1, 4);
  const Variant v{*rc::gen::element(Master::jacobi, Master::gauss_seidel),
                  *rc::gen::element(Protocol::flag, Protocol::epoch), *rc::gen::arbitrary<bool>()};
  const auto seq = *rc::gen::resize(8, arrivals(robots));
  z3::context c;
  Encoding enc(c, v, robots, false);
  z3::solver s(c);
  s.add(enc.init(0));
  const exploration::RobotParams rp;
  auto real = [&](double x) { return c.real_val(std::to_string(x).c_str()); };
  s.add(enc.tolerance() == real(rp.tolerance_m) && enc.orient_tolerance() == real(rp.orient_tolerance_rad) &&
        enc.reorient() == real(rp.reorient_rad));
  for (int i = 0; i < robots; ++i)
    s.add(enc.frame(0).wx[static_cast<std::size_t>(i)] == real(0.5) && enc.frame(0).wy[static_cast<std::size_t>(i)] == real(0.5));
  for (std::size_t t = 0; t < seq.size(); ++t) {
    s.add(enc.trans(static_cast<int>(t)));
    const Step& st = enc.step(static_cast<int>(t));
    for (std::size_t i = 0; i < static_cast<std::size_t>(robots); ++i)
      s.add(st.x[i] == real(seq[t][i] ? 0.5 : 3.5) && st.y[i] == real(0.5) && st.theta[i] == real(0.0) &&
            st.new_wx[i] == real(0.5) && st.new_wy[i] == real(0.5));
  }
  RC_ASSERT(s.check() == z3::sat);
  const z3::model m = s.get_model();
  ConcreteState cs = initial_state(v, robots);
  for (std::size_t t = 0; t < seq.size(); ++t) {
    const StepEvents ev = step(v, rp, cs, poses(seq[t]));
    const Step& st = enc.step(static_cast<int>(t));
    RC_ASSERT(m.eval(st.plan, true).is_true() == ev.plan);
    RC_ASSERT(m.eval(st.early_plan || st.stale_accept, true).is_true() == !ev.violated.empty());
    for (int i = 0; i < robots; ++i)
      RC_ASSERT(m.eval(st.accept[static_cast<std::size_t>(i)], true).is_true() == ev.accept[static_cast<std::size_t>(i)]);
    if (!ev.violated.empty()) break;   // the ghosts' meaning ends at the first violation
  }
}

TEST(HandshakeProof, Z3VerdictsAndTracesThatReadBackAndShow) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("sc-hs-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  for (const char* name : {"handshake-safety", "handshake-epoch-gauss-seidel", "handshake-epoch-late-controller"}) {
    const ObligationReport r = run_in_process(*find_obligation(name), kQueryTimeoutMs);
    EXPECT_EQ(r.result, Verdict::proved) << name << ": " << r.detail;
    EXPECT_FALSE(r.trace.has_value());
  }
  for (const char* name : {"handshake-gauss-seidel", "handshake-late-controller"}) {
    const ObligationReport r = run_in_process(*find_obligation(name), kQueryTimeoutMs);
    EXPECT_EQ(r.result, Verdict::refuted) << name << ": " << r.detail;
    EXPECT_NE(r.detail.find("confirmed by replaying"), std::string::npos) << r.detail;
    ASSERT_TRUE(r.trace.has_value());
    const auto path = dir / r.trace->file_name;
    std::ofstream(path) << r.trace->text;
    const HandshakeTrace t = read_handshake_trace(path.string());
    EXPECT_EQ(t.obligation, name);
    ASSERT_FALSE(t.steps.empty());
    EXPECT_FALSE(t.steps.back().violated.empty());
    std::FILE* out = std::tmpfile();
    EXPECT_EQ(show_handshake_trace(path.string(), out), 0);
    std::fclose(out);
  }
  std::filesystem::remove_all(dir);
}

TEST(HandshakeProof, AMalformedTraceIsAnInputErrorNamingFileAndLine) {
  const auto path = std::filesystem::temp_directory_path() / ("sc-bad-" + std::to_string(::getpid()) + ".jsonl");
  std::ofstream(path) << R"({"format":"swarmcheck-trace","format_version":1,"system":"handshake","obligation":"x","robots":1,"master":"jacobi"})"
                      << "\n"
                      << R"({"step":0,"flag":1,"onDestinationOutput":0,"plan":true,"controllers":[{"onDestinationOutput":1}]})"
                      << "\n";
  try {
    read_handshake_trace(path.string());
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), path.string() + ":2");
    EXPECT_NE(std::string(e.what()).find("arrival"), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace swarmcheck::proofs::handshake
