// swarmcheck_cli_fuzz: a fuzz run over every verb of the binary, from the outside (issue 38).
//
//   swarmcheck_cli_fuzz [--cases N] [--seed S] [--jobs J] [--keep DIR]
//
// N cases (default 10 000) are dealt round-robin to the verbs' case makers below. A case is one
// command line: a shipped input mutated (byte flips, truncation, JSON and .fsm mutations from
// tests/hardening/mutation/mutants.hpp) and flags drawn from valid and invalid values, run
// through the binary under a time limit and a memory cap; for `serve`, one HTTP exchange with a
// server each job starts once. The contract: every command ends with status 0, 1 or 2 (never 3,
// an internal error), is never killed by a signal, and answers within its time limit; every
// server answers each request (never 500) and is still running, then exits 0 on SIGTERM. Inputs
// that ask for unbounded work of a valid kind (a run of 2^31 steps) are drawn again, so a time
// limit that passes is a hang. A failing case is saved under DIR (default
// $TMPDIR/swarmcheck-cli-fuzz-failures) with the command that reproduces it; exit status 1 if
// any case failed. `make fuzz` runs it with 10^4 cases; ctest runs 400 (label hardening).
#include <signal.h>
#include <sys/wait.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "tests/hardening/mutation/mutants.hpp"
#include "tests/hardening/mutation/process.hpp"
#include "tests/hardening/mutation/text.hpp"
#include "tests/util/serve_process.hpp"

namespace fs = std::filesystem;
using namespace swarmcheck::testing::mutation;
namespace st = swarmcheck::testing;

namespace {

// ---- the seed inputs, made once ----------------------------------------------------------------

struct SeedFile {
  std::string name, text;
  bool fsm = false;
  JsonKind kind{"json", false, [](std::size_t, const std::string&) { return false; }};
  std::vector<JTok> toks;
};

struct Seeds {
  fs::path dir;   // fixtures the commands read beside their input (a mission's .fsm, the FMUs)
  std::map<std::string, SeedFile> files;
  const SeedFile& operator[](const std::string& k) const { return files.at(k); }
};

SeedFile json_seed(const std::string& name, const std::string& text, bool lines = false) {
  SeedFile f;
  f.name = name;
  f.text = text;
  f.kind = JsonKind{name, lines, [](std::size_t, const std::string&) { return false; }};
  f.toks = json_tokens(text);
  return f;
}

SeedFile fsm_seed(const std::string& name, const std::string& text) {
  SeedFile f;
  f.name = name;
  f.text = text;
  f.fsm = true;
  return f;
}

void must(const Outcome& o, const std::string& what) {
  if (o.status == 0 || o.status == 1) return;
  std::fprintf(stderr, "cli_fuzz: cannot make the seed %s: status %d\n%s%s", what.c_str(), o.status, o.out.c_str(), o.err.c_str());
  std::exit(2);
}

Seeds make_seeds(const fs::path& dir) {
  Seeds s;
  s.dir = dir / "fixtures";
  fs::create_directories(s.dir);
  const auto src = [](const std::string& p) { return read_bytes(kSource + "/" + p); };
  s.files["scenario"] = json_seed("scenario.json", src("scenarios/default.json"));
  s.files["warehouse"] = json_seed("warehouse.json", src("scenarios/examples/warehouse.json"));
  s.files["mission"] = json_seed("mission.json", src("scenarios/thesis/thesis-mission.json"));
  s.files["walls"] = json_seed("walls.json", src("scenarios/examples/walls.json"));
  s.files["dse"] = json_seed("ertu.dse.json", src("scenarios/thesis/dse/ertu.dse.json"));
  s.files["dse_base"] = json_seed("base.json", src("scenarios/thesis/dse/base.json"));
  for (const std::string f : {"control2.fsm", "supervisor.fsm"}) s.files[f] = fsm_seed(f, src("scenarios/thesis/" + f));
  for (const std::string f : {"region_a.fsm", "tasks_a.fsm", "avoidance.fsm", "located.fsm"})
    s.files[f] = fsm_seed(f, src("scenarios/thesis/components/" + f));
  // Fixtures beside the inputs: the FSMs missions name.
  for (const std::string f : {"control2.fsm"}) write_bytes(s.dir / f, src("scenarios/thesis/" + f));
  for (const std::string f : {"one-at-a-time.fsm", "two-tasks.fsm"}) write_bytes(s.dir / f, src("scenarios/examples/" + f));
  // A run trace with field records, a mission trace, a proof's counterexample trace.
  const fs::path t = dir / "t.jsonl";
  must(run_swarmcheck({"run", "--mode", "abstract", "--steps", "40", "--trace", t.string(), "--trace-field", "10"}, std::chrono::seconds(60)), "run trace");
  s.files["trace"] = json_seed("t.jsonl", read_bytes(t), true);
  const fs::path m = dir / "m.jsonl";
  write_bytes(s.dir / "thesis-mission.json", src("scenarios/thesis/thesis-mission.json"));
  must(run_swarmcheck({"mission", "run", (s.dir / "thesis-mission.json").string(), "--body", "kinematic", "--speed", "50",
                       "--max-time", "30", "--trace", m.string()}, std::chrono::seconds(60)), "mission trace");
  s.files["mission_trace"] = json_seed("m.jsonl", read_bytes(m), true);
  const fs::path proofs = dir / "proofs";
  must(run_swarmcheck({"prove", "--only", "handshake-gauss-seidel", "--trace-dir", proofs.string()}, std::chrono::seconds(120)), "proof trace");
  for (const auto& e : fs::directory_iterator(proofs))
    if (e.path().extension() == ".jsonl") s.files["proof_trace"] = json_seed("p.jsonl", read_bytes(e.path()), true);
  // The thesis multi-model's FMUs, and its configurations with a short end time.
  const fs::path fmus = dir / "intocps";
  must(run_swarmcheck({"fmu", "export", "--intocps", fmus.string()}, std::chrono::seconds(120)), "FMUs");
  for (const std::string f : {"Environment.fmu", "Controller.fmu", "Body.fmu"}) fs::copy_file(fmus / f, s.dir / f, fs::copy_options::overwrite_existing);
  s.files["multimodel"] = json_seed("multimodel.json", read_bytes(fmus / "multimodel.json"));
  std::string coe = read_bytes(fmus / "coe.json");
  {
    const std::size_t at = coe.find("\"endTime\": ") + 11;   // the exported end, whatever it is
    coe.replace(at, coe.find_first_of(",\n", at) - at, "5");
  }
  s.files["coe"] = json_seed("coe.json", coe);
  // The FMU's own resource file, mutated into a copy of the FMU.
  const fs::path unpacked = dir / "env";
  fs::create_directories(unpacked);
  if (std::system(("cd '" + unpacked.string() + "' && unzip -q -o '" + (fmus / "Environment.fmu").string() + "'").c_str()) != 0) {
    std::fprintf(stderr, "cli_fuzz: unzip failed\n");
    std::exit(2);
  }
  s.files["fmu_resource"] = json_seed("swarmcheck-fmu.json", read_bytes(unpacked / "resources" / "swarmcheck-fmu.json"));
  s.files["control_body"] = json_seed("control.json", R"({"paused": true, "steps_per_frame": 10})");
  return s;
}

// ---- mutation, bounded ---------------------------------------------------------------------------

// A mutant of `f` (or, one time in eight, `f` itself); `bounded` says whether a mutant may run
// (a valid input asking for unbounded work is drawn again).
std::string mutate(Rng& rng, const SeedFile& f, const std::function<bool(const std::string&)>& bounded = nullptr) {
  if (below(rng, 8) == 0) return f.text;
  for (int tries = 0; tries < 20; ++tries) {
    std::string t;
    if (f.fsm) t = fsm_mutant(rng, kFsmOps[below(rng, kFsmOps.size())], f.text).text;
    else t = json_mutant(rng, kJsonOps[below(rng, kJsonOps.size())], f.text, f.toks, f.kind).text;
    if (!bounded || bounded(t)) return t;
  }
  return f.text;
}

// Whether every number at a key named `key`, anywhere in the JSON text, is at most `max` (text
// that is not JSON is bounded: it is refused before any work).
bool numbers_at_most(const std::string& text, const std::vector<std::string>& keys, double max) {
  const auto j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded()) return true;
  bool ok = true;
  // Mutants nest 100 000 deep: the walk stops at the binary's own limit (512, refused before any
  // work), or it would overflow this thread's stack.
  std::function<void(const nlohmann::json&, int)> walk = [&](const nlohmann::json& v, int depth) {
    if (depth > 600) return;
    if (v.is_object()) {
      for (auto it = v.begin(); it != v.end(); ++it) {
        for (const auto& k : keys)
          if (it.key().find(k) != std::string::npos) {
            if (it->is_number() && !(it->get<double>() <= max)) ok = false;
            if (it->is_array())
              for (const auto& e : *it)
                if (e.is_number() && !(e.get<double>() <= max)) ok = false;
          }
        walk(*it, depth + 1);
      }
    } else if (v.is_array()) {
      for (const auto& e : v) walk(e, depth + 1);
    }
  };
  walk(j, 0);
  return ok;
}

// ---- the cases -------------------------------------------------------------------------------------

struct Case {
  std::string verb;
  std::vector<std::string> args;
  std::chrono::milliseconds limit{30000};
  std::vector<std::pair<std::string, std::string>> files;   // name -> bytes, written into the case's folder first
  std::string fmu_resource;                                  // when set: a copy of Environment.fmu with this resource file
};

template <class T>
const T& one_of(Rng& rng, const std::vector<T>& v) {
  return v[below(rng, v.size())];
}

std::string any_int(Rng& rng) {
  return one_of<std::string>(rng, {"0", "1", "2", "7", "-1", "1e3", "x", "", "99999999999999999999", "2147483648", "0x10", "3.5"});
}

using Maker = std::function<Case(Rng&, const Seeds&, const fs::path& dir)>;

std::vector<std::pair<std::string, Maker>> makers() {
  std::vector<std::pair<std::string, Maker>> m;
  const auto in = [](const fs::path& dir, const std::string& name) { return (dir / name).string(); };
  m.emplace_back("run", [in](Rng& rng, const Seeds& s, const fs::path& dir) {
    Case c;
    c.verb = "run";
    const SeedFile& f = below(rng, 3) ? s["scenario"] : s["warehouse"];
    c.files.emplace_back("in.json", mutate(rng, f, [](const std::string& t) { return numbers_at_most(t, {"map_size"}, 2048); }));
    c.args = {"run", in(dir, "in.json"), "--steps", one_of<std::string>(rng, {"0", "1", "50", "300", "-5", "x"}), "--memory-limit", "512M"};
    if (below(rng, 2)) c.args.insert(c.args.end(), {"--mode", one_of<std::string>(rng, {"abstract", "cosim", "other"})});
    if (below(rng, 2)) c.args.insert(c.args.end(), {"--rule", one_of<std::string>(rng, {"thesis", "deterministic", "stochastic", ""})});
    if (below(rng, 2)) c.args.insert(c.args.end(), {"--trace", in(dir, "out.jsonl"), "--trace-every", any_int(rng)});
    if (below(rng, 3) == 0) c.args.insert(c.args.end(), {"--trace-field", any_int(rng)});
    if (below(rng, 3) == 0) c.args.insert(c.args.end(), {"--svg", in(dir, below(rng, 2) ? "out.svg" : "in.json")});
    if (below(rng, 3) == 0) c.args.insert(c.args.end(), {"--seed", any_int(rng)});
    if (below(rng, 3) == 0) c.args.insert(c.args.end(), {"--threads", one_of<std::string>(rng, {"1", "2", "0", "-1", "4096"})});
    if (below(rng, 2)) c.args.push_back("--json");
    return c;
  });
  m.emplace_back("replay", [in](Rng& rng, const Seeds& s, const fs::path& dir) {
    Case c;
    c.verb = "replay";
    c.files.emplace_back("t.jsonl", mutate(rng, s["trace"], [](const std::string& t) {
      const std::string head = t.substr(0, t.find('\n'));
      return numbers_at_most(head, {"map_size"}, 256) && numbers_at_most(head, {"max_steps"}, 5000);
    }));
    c.args = {"replay", in(dir, "t.jsonl"), "--memory-limit", "512M"};
    if (below(rng, 2)) c.args.insert(c.args.end(), {"--against", one_of<std::string>(rng, {"model", "impl", "both"})});
    return c;
  });
  m.emplace_back("conform", [](Rng& rng, const Seeds&, const fs::path& dir) {
    Case c;
    c.verb = "conform";
    c.args = {"conform", "--cases", one_of<std::string>(rng, {"1", "2", "0", "-3", "x"}), "--max-steps", one_of<std::string>(rng, {"20", "50", "0", "1e9"}),
              "--out", (dir / "cx").string()};
    c.args.insert(c.args.end(), {"--system", one_of<std::string>(rng, {"exploration", "automata", "missions", "nope"})});
    if (below(rng, 2)) c.args.insert(c.args.end(), {"--seed", any_int(rng)});
    if (below(rng, 3) == 0) c.args.push_back("--json");
    c.limit = std::chrono::seconds(60);
    return c;
  });
  m.emplace_back("prove", [](Rng& rng, const Seeds&, const fs::path& dir) {
    Case c;
    c.verb = "prove";
    c.args = {"prove", "--only", one_of<std::string>(rng, {"servo-saturation", "atan2-fix", "nope", ""}), "--timeout",
              one_of<std::string>(rng, {"20", "0", "-1", "x"})};
    if (below(rng, 2)) c.args.insert(c.args.end(), {"--trace-dir", (dir / "traces").string()});
    if (below(rng, 2)) c.args.insert(c.args.end(), {"--smt2", (dir / "smt2").string()});
    if (below(rng, 2)) c.args.push_back("--json");
    c.limit = std::chrono::seconds(90);
    return c;
  });
  m.emplace_back("fsm", [in](Rng& rng, const Seeds& s, const fs::path& dir) {
    Case c;
    c.verb = "fsm";
    const std::vector<std::string> names{"control2.fsm", "supervisor.fsm", "region_a.fsm", "tasks_a.fsm", "avoidance.fsm", "located.fsm"};
    const std::string a = one_of(rng, names), b = one_of(rng, names);
    c.files.emplace_back("a.fsm", mutate(rng, s[a]));
    c.files.emplace_back("b.fsm", below(rng, 2) ? s[b].text : mutate(rng, s[b]));
    const std::string A = in(dir, "a.fsm"), B = in(dir, "b.fsm"), out = in(dir, "out.fsm");
    const std::vector<std::string> limits{"--memory-limit", "256M", "--time-limit", "10"};
    switch (below(rng, 9)) {
      case 0: c.args = {"fsm", "check", A}; break;
      case 1: c.args = {"fsm", "product", A, B, "-o", out}; c.args.insert(c.args.end(), limits.begin(), limits.end()); break;
      case 2: c.args = {"fsm", "synth", "--plant", A, "--spec", B, "-o", out}; c.args.insert(c.args.end(), limits.begin(), limits.end()); break;
      case 3: c.args = {"fsm", "export", A, "--to", one_of<std::string>(rng, {"dot", "json", "fsm", "svg", "png"}), "-o", in(dir, "out.txt")}; break;
      case 4: c.args = {"fsm", "compare", A, B}; c.args.insert(c.args.end(), limits.begin(), limits.end()); break;
      case 5: c.args = {"fsm", "controllable", "--plant", A, "--sup", B}; c.args.insert(c.args.end(), limits.begin(), limits.end()); break;
      case 6: c.args = {"fsm", "observable", "--plant", A, "--spec", B}; c.args.insert(c.args.end(), limits.begin(), limits.end()); break;
      case 7: c.args = {"fsm", "project", A, "-o", out}; c.args.insert(c.args.end(), limits.begin(), limits.end()); break;
      default: c.args = {"fsm", "check", A, "--engine", one_of<std::string>(rng, {"model", "impl", "x"})}; break;
    }
    if (below(rng, 3) == 0) c.args.push_back("--json");
    return c;
  });
  m.emplace_back("mission", [in](Rng& rng, const Seeds& s, const fs::path& dir) {
    Case c;
    c.verb = "mission";
    const bool walls = below(rng, 4) == 0;
    c.files.emplace_back("in.json", mutate(rng, walls ? s["walls"] : s["mission"], [](const std::string& t) {
      return numbers_at_most(t, {"beams"}, 4096) && numbers_at_most(t, {"resolution_m"}, 1e9);
    }));
    c.files.emplace_back(walls ? "one-at-a-time.fsm" : "control2.fsm",
                         read_bytes(s.dir / (walls ? "one-at-a-time.fsm" : "control2.fsm")));
    if (below(rng, 2)) {
      c.args = {"mission", "plan", in(dir, "in.json")};
      if (below(rng, 2)) c.args.insert(c.args.end(), {"--planner", one_of<std::string>(rng, {"thesis", "exact", "x"})});
    } else {
      c.args = {"mission", "run", in(dir, "in.json"), "--max-time", one_of<std::string>(rng, {"20", "200", "0", "-1"}), "--memory-limit", "256M"};
      if (below(rng, 2)) c.args.insert(c.args.end(), {"--body", one_of<std::string>(rng, {"kinematic", "unicycle", "x"})});
      if (below(rng, 2)) c.args.insert(c.args.end(), {"--trace", in(dir, "out.jsonl")});
      if (below(rng, 3) == 0) c.args.insert(c.args.end(), {"--svg", in(dir, "out.svg")});
      if (below(rng, 3) == 0) c.args.insert(c.args.end(), {"--dt", one_of<std::string>(rng, {"0.05", "0.5", "0", "-1", "x"})});
    }
    if (below(rng, 3) == 0) c.args.push_back("--json");
    return c;
  });
  m.emplace_back("dse", [in](Rng& rng, const Seeds& s, const fs::path& dir) {
    Case c;
    c.verb = "dse";
    const auto small = [](const std::string& t) {
      return numbers_at_most(t, {"max_steps", "maxSteps", "initialPopulation", "maxGeneration", "replicates", "seed"}, 400) &&
             numbers_at_most(t, {"map_size", "mapSize", "nRobots", "n_robots"}, 32) && t.size() < 4000;
    };
    c.files.emplace_back("c.dse.json", mutate(rng, s["dse"], small));
    c.files.emplace_back("base.json", below(rng, 2) ? s["dse_base"].text : mutate(rng, s["dse_base"], small));
    c.args = {"dse", in(dir, "c.dse.json"), "--scenario", in(dir, "base.json"), "-o", in(dir, "out"), "--threads",
              one_of<std::string>(rng, {"1", "2"}), "--memory-limit", "512M"};
    if (below(rng, 3) == 0) c.args.push_back("--json");
    c.limit = std::chrono::seconds(60);
    return c;
  });
  m.emplace_back("view", [in](Rng& rng, const Seeds& s, const fs::path& dir) {
    Case c;
    c.verb = "view";
    switch (below(rng, 4)) {
      case 0: c.files.emplace_back("in.jsonl", mutate(rng, s["trace"])); break;
      case 1: c.files.emplace_back("in.jsonl", mutate(rng, s["mission_trace"])); break;
      case 2: c.files.emplace_back("in.jsonl", mutate(rng, s["proof_trace"])); break;
      default: c.files.emplace_back("in.jsonl", mutate(rng, s["control2.fsm"])); break;
    }
    c.files.emplace_back("thesis-mission.json", s["mission"].text);
    c.files.emplace_back("control2.fsm", s["control2.fsm"].text);
    c.args = {"view", in(dir, "in.jsonl"), "-o", in(dir, "out.html")};
    if (below(rng, 2)) c.args.insert(c.args.end(), {"--mission", in(dir, "thesis-mission.json")});
    if (below(rng, 3) == 0) c.args.insert(c.args.end(), {"--max-records", any_int(rng)});
    return c;
  });
  m.emplace_back("edit", [in](Rng& rng, const Seeds& s, const fs::path& dir) {
    Case c;
    c.verb = "edit";
    const bool mission = below(rng, 2);
    c.files.emplace_back("in.json", mutate(rng, mission ? s["mission"] : s["scenario"]));
    c.files.emplace_back("control2.fsm", s["control2.fsm"].text);
    c.args = {"edit", in(dir, "in.json"), "-o", in(dir, "out.html")};
    return c;
  });
  m.emplace_back("fmu", [in](Rng& rng, const Seeds& s, const fs::path& dir) {
    Case c;
    c.verb = "fmu";
    c.files.emplace_back("s.json", mutate(rng, s["scenario"], [](const std::string& t) { return numbers_at_most(t, {"map_size"}, 4096); }));
    c.args = {"fmu", "export", one_of<std::string>(rng, {"environment", "controller", "body", "x"}), "-o", in(dir, "out.fmu")};
    if (below(rng, 2)) c.args.insert(c.args.end(), {"--scenario", in(dir, "s.json")});
    if (below(rng, 3) == 0) c.args.insert(c.args.end(), {"--robots", one_of<std::string>(rng, {"1", "4", "0", "-2", "100000", "x"})});
    if (below(rng, 3) == 0) c.args.insert(c.args.end(), {"--handshake", one_of<std::string>(rng, {"flag", "epoch", "x"})});
    return c;
  });
  m.emplace_back("cosim", [in](Rng& rng, const Seeds& s, const fs::path& dir) {
    Case c;
    c.verb = "cosim";
    const auto short_run = [](const std::string& t) { return numbers_at_most(t, {"endTime"}, 20); };
    const std::size_t what = below(rng, 3);
    c.files.emplace_back("multimodel.json", what == 0 ? mutate(rng, s["multimodel"]) : s["multimodel"].text);
    c.files.emplace_back("coe.json", what == 1 ? mutate(rng, s["coe"], short_run) : s["coe"].text);
    if (what == 2) c.fmu_resource = mutate(rng, s["fmu_resource"], [](const std::string& t) { return numbers_at_most(t, {"map_size"}, 256); });
    c.args = {"cosim", in(dir, "multimodel.json"), "--config", in(dir, "coe.json"), "-o", in(dir, "out.csv")};
    if (below(rng, 3) == 0) c.args.insert(c.args.end(), {"--algorithm", one_of<std::string>(rng, {"jacobi", "gauss-seidel", "x"})});
    if (below(rng, 3) == 0) c.args.push_back("--json");
    c.limit = std::chrono::seconds(60);
    return c;
  });
  m.emplace_back("serve", [](Rng&, const Seeds&, const fs::path&) {
    Case c;
    c.verb = "serve";
    return c;
  });
  return m;
}

// ---- serve: one HTTP exchange ----------------------------------------------------------------

std::string http_request(Rng& rng, const Seeds& s, int port) {
  const std::string me = "127.0.0.1:" + std::to_string(port);
  std::string method = one_of<std::string>(rng, {"GET", "POST", "POST", "POST", "PUT", "OPTIONS", "DELETE", "HEAD", "G\x01T", "POST"});
  std::string path = one_of<std::string>(rng, {"/", "/editor", "/api/schema", "/api/view", "/api/validate", "/api/runs",
                                                "/api/runs?steps_per_frame=10", "/api/runs?steps_per_frame=0",
                                                "/api/runs/0123456789abcdef/events", "/api/runs/0123456789abcdef/control",
                                                "/../../etc/passwd", "/api/%00", "*", ""});
  std::string body;
  switch (below(rng, 5)) {
    case 0: body = mutate(rng, s["scenario"]); break;
    case 1: body = mutate(rng, s["control_body"]); break;
    case 2: {
      nlohmann::json v{{"name", one_of<std::string>(rng, {"t.jsonl", "a.fsm", "", "../x", "a\nb"})},
                       {"text", below(rng, 2) ? mutate(rng, s["trace"]) : mutate(rng, s["control2.fsm"])}};
      body = v.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
      if (below(rng, 4) == 0) body = body.substr(0, below(rng, body.size() + 1));
      break;
    }
    case 3: body = std::string(below(rng, 3000), static_cast<char>('a' + below(rng, 26))); break;
    default: break;
  }
  std::string r = method + " " + path + " HTTP/1." + one_of<std::string>(rng, {"1", "1", "0", "9"}) + "\r\n";
  if (below(rng, 10)) r += "Host: " + one_of<std::string>(rng, {me, me, "localhost:" + std::to_string(port), "evil.example", me + ":1"}) + "\r\n";
  if (below(rng, 3) == 0) r += "Origin: " + one_of<std::string>(rng, {"http://" + me, "http://evil.example", "null"}) + "\r\n";
  if (below(rng, 4)) r += "Content-Type: " + one_of<std::string>(rng, {"application/json", "application/json", "text/plain", "application/x-www-form-urlencoded"}) + "\r\n";
  if (below(rng, 4) == 0) r += "Sec-Fetch-Site: " + one_of<std::string>(rng, {"same-origin", "cross-site", "none"}) + "\r\n";
  const std::size_t len_kind = below(rng, 8);
  if (len_kind == 0) r += "Transfer-Encoding: chunked\r\n";
  else if (len_kind == 1) r += "Content-Length: " + one_of<std::string>(rng, {"-1", "99999999999999999999", "x", "0"}) + "\r\n";
  else if (len_kind != 2) r += "Content-Length: " + std::to_string(body.size()) + "\r\n";
  for (std::size_t k = below(rng, 4) == 0 ? below(rng, 150) : 0; k > 0; --k) r += "X-" + std::to_string(k) + ": y\r\n";
  r += "\r\n";
  if (len_kind == 0) {
    char size[32];
    std::snprintf(size, sizeof size, "%zx\r\n", body.size());
    r += size + body + "\r\n0\r\n\r\n";
  } else {
    r += body;
  }
  return r;
}

// ---- the run -------------------------------------------------------------------------------------

struct Failure {
  std::size_t index;
  std::string verb, what, command;
};

struct Tally {
  std::mutex mutex;
  std::map<std::string, std::map<std::string, int>> by_verb;   // verb -> outcome -> count
  std::vector<Failure> failures;
};

void write_case_files(const Case& c, const fs::path& dir, const Seeds& s) {
  for (const auto& [name, bytes] : c.files) write_bytes(dir / name, bytes);
  if (c.verb == "cosim") {
    for (const std::string f : {"Controller.fmu", "Body.fmu", "Environment.fmu"}) fs::copy_file(s.dir / f, dir / f, fs::copy_options::overwrite_existing);
    if (!c.fmu_resource.empty()) {
      fs::create_directories(dir / "resources");
      write_bytes(dir / "resources" / "swarmcheck-fmu.json", c.fmu_resource);
      const std::string cmd = "cd '" + dir.string() + "' && zip -q Environment.fmu resources/swarmcheck-fmu.json";
      if (std::system(cmd.c_str()) != 0) std::fprintf(stderr, "cli_fuzz: zip failed in %s\n", dir.string().c_str());
      fs::remove_all(dir / "resources");
    }
  }
}

std::string shell_words(const std::vector<std::string>& args) {
  std::string r = kBin;
  for (const auto& a : args) {
    r += " '";
    for (const char c : a) r += c == '\'' ? std::string("'\\''") : std::string(1, c);
    r += "'";
  }
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t cases = 10000, jobs = std::max(1u, std::thread::hardware_concurrency());
  std::uint64_t seed = 1;
  fs::path keep = fs::temp_directory_path() / "swarmcheck-cli-fuzz-failures";
  for (int k = 1; k + 1 < argc; k += 2) {
    const std::string a = argv[k];
    if (a == "--cases") cases = std::strtoull(argv[k + 1], nullptr, 10);
    else if (a == "--seed") seed = std::strtoull(argv[k + 1], nullptr, 10);
    else if (a == "--jobs") jobs = std::max<std::size_t>(1, std::strtoull(argv[k + 1], nullptr, 10));
    else if (a == "--keep") keep = argv[k + 1];
    else {
      std::fprintf(stderr, "usage: swarmcheck_cli_fuzz [--cases N] [--seed S] [--jobs J] [--keep DIR]\n");
      return 2;
    }
  }
  const fs::path work = fs::temp_directory_path() / ("swarmcheck-cli-fuzz-" + std::to_string(::getpid()));
  fs::create_directories(work);
  const Seeds seeds = make_seeds(work);
  const auto all = makers();
  const auto scale = kAddressSanitizer ? 4 : 1;
  Tally tally;
  std::atomic<std::size_t> next{0};
  const auto start = std::chrono::steady_clock::now();
  const auto worker = [&](std::size_t job) {
    std::unique_ptr<st::ServeProcess> server;
    for (std::size_t i; (i = next.fetch_add(1)) < cases;) {
      Rng rng(seed * 0x9e3779b97f4a7c15ull + i);
      const auto& [verb, make] = all[i % all.size()];
      const fs::path dir = work / ("job" + std::to_string(job)) / ("case" + std::to_string(i));
      fs::create_directories(dir);
      std::string outcome, failure, command;
      if (verb == "serve") {
        if (!server || !server->running()) server = std::make_unique<st::ServeProcess>(kBin, std::vector<std::string>{"--request-timeout", "2"});
        const std::string request = http_request(rng, seeds, server->port());
        const st::HttpReply r = st::http_raw(server->port(), request, std::chrono::seconds(30 * scale));
        outcome = r.status == 0 ? "closed" : std::to_string(r.status);
        if (r.status >= 500 && r.status != 503) failure = "HTTP " + std::to_string(r.status) + ": " + r.body.substr(0, 200);
        else if (!server->running()) failure = "the server died";
        if (!failure.empty()) {
          fs::create_directories(keep);
          write_bytes(keep / ("case" + std::to_string(i) + ".http"), request);
          command = "the request in " + (keep / ("case" + std::to_string(i) + ".http")).string() + " to swarmcheck serve";
        }
      } else {
        Case c = make(rng, seeds, dir);
        write_case_files(c, dir, seeds);
        const Outcome o = run_swarmcheck(c.args, c.limit * scale, 2048);
        outcome = o.timed_out ? "timeout" : o.signal ? "signal " + std::to_string(o.signal) : "status " + std::to_string(o.status);
        if (o.timed_out) failure = "no answer within " + std::to_string(c.limit.count() / 1000 * scale) + " s (a hang)";
        else if (o.signal) failure = std::string("killed by ") + strsignal(o.signal);
        else if (o.status < 0 || o.status > 2) failure = "exit status " + std::to_string(o.status) + ": " + o.err.substr(0, 300);
        if (!failure.empty()) {
          const fs::path saved = keep / ("case" + std::to_string(i));
          fs::create_directories(saved);
          for (const auto& e : fs::directory_iterator(dir)) fs::copy(e.path(), saved / e.path().filename(), fs::copy_options::recursive | fs::copy_options::overwrite_existing);
          std::vector<std::string> args = c.args;
          for (auto& a : args)
            if (a.rfind(dir.string(), 0) == 0) a = (saved / a.substr(dir.string().size() + 1)).string();
          command = shell_words(args);
        }
      }
      std::error_code ignored;
      fs::remove_all(dir, ignored);
      std::lock_guard lock(tally.mutex);
      ++tally.by_verb[verb][outcome];
      if (!failure.empty()) tally.failures.push_back({i, verb, failure, command});
    }
    if (server) {
      const auto status = server->stop(SIGTERM, std::chrono::seconds(10));
      std::lock_guard lock(tally.mutex);
      if (!status || !WIFEXITED(*status) || WEXITSTATUS(*status) != 0)
        tally.failures.push_back({cases, "serve", "the server did not exit 0 on SIGTERM", ""});
    }
  };
  std::vector<std::thread> threads;
  for (std::size_t j = 0; j < jobs; ++j) threads.emplace_back(worker, j);
  for (auto& t : threads) t.join();
  std::error_code ignored;
  fs::remove_all(work, ignored);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("cli_fuzz: %zu cases over %zu verbs, seed %llu, %zu jobs, %.0f s\n", cases, all.size(),
              static_cast<unsigned long long>(seed), jobs, seconds);
  for (const auto& [verb, outcomes] : tally.by_verb) {
    std::printf("  %-8s", verb.c_str());
    for (const auto& [o, n] : outcomes) std::printf("  %s: %d", o.c_str(), n);
    std::printf("\n");
  }
  for (const Failure& f : tally.failures)
    std::printf("FAIL case %zu (%s): %s\n  %s\n", f.index, f.verb.c_str(), f.what.c_str(), f.command.c_str());
  std::printf("%zu crashes, exit status 3 or hangs\n", tally.failures.size());
  return tally.failures.empty() ? 0 : 1;
}
