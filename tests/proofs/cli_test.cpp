// The prove verb end to end (through the private CLI that wires it as main.cpp does): every
// verdict is met, bad input gives status 2, and the SMT-LIB2 files re-check with the z3 binary.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct CommandResult {
  int status;
  std::string out;
};

CommandResult run(const std::string& command) {
  CommandResult r{-1, ""};
  FILE* p = ::popen((command + " 2>&1").c_str(), "r");
  if (p == nullptr) return r;
  std::array<char, 4096> buf{};
  std::size_t n = 0;
  while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  const int st = ::pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

std::string prove(const std::string& args) { return std::string(SWARMCHECK_PROVE_BIN) + " prove " + args; }

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("swarmcheck-proofs-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(d);
  return d;
}

TEST(ProveCli, JsonListsEveryObligationWithItsExpectedVerdictAllMet) {
  const CommandResult r = run(prove("--json"));
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j.at("all_met").get<bool>());
  std::set<std::string> names;
  double seconds = 0;
  for (const auto& o : j.at("obligations")) {
    names.insert(o.at("name").get<std::string>());
    seconds += o.at("seconds").get<double>();
    EXPECT_TRUE(o.at("met").get<bool>()) << o.dump(2);
    EXPECT_EQ(o.at("result"), o.at("expected")) << o.dump(2);
    EXPECT_FALSE(o.at("assumptions").empty());
    // What a proof is about is the code: every obligation expected to hold reads spec functions,
    // and reads every function the step calls on its property's path (nothing unread).
    if (o.at("expected") == "proved") {
      EXPECT_FALSE(o.at("reads").empty()) << o.dump(2);
      for (const auto& f : o.at("reads")) EXPECT_EQ(f.get<std::string>().rfind("exploration::", 0), 0U) << f;
    }
    EXPECT_TRUE(o.at("unread").empty()) << o.dump(2);
    const auto reads = o.at("reads").get<std::vector<std::string>>();
    for (const auto& f : o.at("step_calls"))
      EXPECT_NE(std::find(reads.begin(), reads.end(), f.get<std::string>()), reads.end()) << o.at("name") << ": " << f;
  }
  for (const char* required : {"servo-saturation", "servo-thesis-clamp", "servo-controller-range", "atan2-fix",
                               "atan2-without-fix", "handshake-safety", "handshake-gauss-seidel",
                               "handshake-late-controller", "handshake-epoch-gauss-seidel",
                               "handshake-epoch-late-controller", "handshake-safety-any-robots",
                               "all-arrived-any-robots", "handshake-epoch-any-robots", "handshake-epoch-late-any-robots",
                               "pheromone-bounds", "occupancy"})
    EXPECT_TRUE(names.count(required)) << required;
  // The total is what the obligations took (no timing bound here: the machine's load decides the
  // seconds; docs/proofs.md states the measured figure).
  EXPECT_DOUBLE_EQ(j.at("total_seconds").get<double>(), seconds);
}

TEST(ProveCli, RefutedProtocolObligationsWriteTheirTraces) {
  const fs::path dir = fresh_dir("traces");
  const CommandResult r = run(prove("--only handshake-late-controller --trace-dir " + dir.string()));
  EXPECT_EQ(r.status, 0) << r.out;
  std::ifstream in(dir / "handshake-late-controller.jsonl");
  std::string header;
  std::getline(in, header);
  const auto h = nlohmann::json::parse(header);
  EXPECT_EQ(h.at("system"), "handshake");
  EXPECT_EQ(h.at("master"), "jacobi");
  EXPECT_EQ(h.at("controller"), "late");
  fs::remove_all(dir);
}

TEST(ProveCli, AnUnknownObligationNameIsBadInputAndListsTheValidNames) {
  const CommandResult r = run(prove("--only no-such-thing"));
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("no-such-thing"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("servo-saturation"), std::string::npos) << r.out;
}

TEST(ProveCli, OnlyRunsOneObligationAndPrintsTheTable) {
  const CommandResult r = run(prove("--only servo-thesis-clamp"));
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("servo-thesis-clamp"), std::string::npos);
  EXPECT_NE(r.out.find("refuted"), std::string::npos);
  EXPECT_EQ(r.out.find("pheromone-bounds"), std::string::npos);
}

// Every query file re-checked by the z3 binary gives the answer the C++ API gave.
TEST(ProveCli, EverySmt2FileRechecksWithTheZ3BinaryToTheSameAnswer) {
  const fs::path dir = fresh_dir("smt2");
  const CommandResult r = run(prove("--json --smt2 " + dir.string()));
  ASSERT_EQ(r.status, 0) << r.out;
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() != ".smt2") continue;
    ++files;
    std::ifstream in(e.path());
    std::string first, second;
    std::getline(in, first);
    std::getline(in, second);
    ASSERT_EQ(second.rfind("; expect: ", 0), 0U) << e.path();
    const std::string expect = second.substr(10);
    const CommandResult z = run(std::string(SWARMCHECK_Z3_BIN) + " -T:60 " + e.path().string());
    std::string answer = z.out.substr(0, z.out.find('\n'));
    EXPECT_EQ(answer, expect) << e.path() << "\n" << z.out;
  }
  EXPECT_GT(files, 20);
  fs::remove_all(dir);
}

}  // namespace
