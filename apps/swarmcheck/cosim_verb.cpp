// swarmcheck cosim: runs an INTO-CPS multi-model with swarmcheck's fixed-step master
// (fmi/master/master.hpp), which does what the INTO-CPS engine does (start values, time by
// repeated addition), and writes outputs.csv in the engine's format (fmi/master/outputs_csv.hpp);
// on swarmcheck's own FMUs it also watches the onDestination handshake
// (fmi/master/handshake_monitor.hpp). An FMU call that does not return within --step-timeout
// stops the run (status 1), the FMUs freed and their folders removed.
#include <fmt/core.h>
#include <fmt/ostream.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>

#include "apps/swarmcheck/fmu_verb.hpp"
#include "apps/swarmcheck/stop_request.hpp"
#include "apps/swarmcheck/verb.hpp"
#include "fmi/master/handshake_monitor.hpp"
#include "fmi/master/master.hpp"
#include "fmi/master/outputs_csv.hpp"
#include "impl/io/atomic_file.hpp"
#include "impl/io/interrupt.hpp"
#include "spec/util/hana_json.hpp"

namespace swarmcheck::cli {
namespace {

struct CosimOptions {
  std::string multimodel;
  std::string config;
  std::string algorithm = "jacobi";
  std::string output;
  double step_timeout_s = 10;
  bool json = false;
};


int run_cosim(const CosimOptions& o) {
  namespace fm = swarmcheck::fmi::master;
  const fm::MultiModel mm = fm::read_multimodel(o.multimodel);
  const fm::CoSimConfig config = fm::read_config(o.config);
  std::vector<std::string> inputs{o.multimodel, o.config};
  for (const auto& [key, file] : mm.fmus) inputs.push_back(file);
  io::refuse_output_that_is_an_input(o.output, inputs);
  // Ctrl-C / SIGTERM stop between steps, so the FMU instances are freed and their unpacked
  // folders removed (the Master's destructor) before the process exits 130 / 143.
  const StopRequest stop("\nswarmcheck cosim: interrupted: unloading the FMUs (Ctrl-C again to stop now)\n");
  fm::Master master(mm, config,
                    fm::MasterOptions{o.algorithm == "gauss-seidel" ? fm::Algorithm::gauss_seidel : fm::Algorithm::jacobi,
                                      o.step_timeout_s});
  fm::HandshakeMonitor monitor(master);
  std::unique_ptr<io::AtomicFile> csv;
  const fm::OutputsCsv outputs(master);
  if (!o.output.empty()) {
    csv = std::make_unique<io::AtomicFile>(o.output);
    master.remove_if_abandoned(csv->temp_path());
    outputs.header(csv->stream());
    outputs.row(csv->stream(), master.time_s(), 0.0);
  }
  // eP of a swarmcheck Environment, for the summary.
  std::optional<fm::Master::Port> eP;
  for (const std::string& in : master.instance_names())
    if (master.model_name_of(in).rfind("swarmcheck Environment", 0) == 0) eP = master.port(in + ".eP");   // either interface
  std::optional<int64_t> complete_at;
  while (!master.done()) {
    if (stop.requested()) {
      fmt::print(stderr, "swarmcheck cosim: interrupted at t = {} s after {} steps; FMUs unloaded, {}\n",
                 master.time_s(), master.steps(), o.output.empty() ? "nothing written" : o.output + " left as it was");
      return stop.exit_status();
    }
    master.step();
    monitor.after_step(master);
    if (eP && !complete_at && master.value(*eP) >= 100) complete_at = master.steps();
    if (csv) outputs.row(csv->stream(), master.time_s(), master.step_size_s());
  }
  if (csv) csv->commit();
  const bool violated = monitor.active() && monitor.stale_count() > 0;
  if (o.json) {
    json_io::Json j;
    j["multimodel"] = o.multimodel;
    j["algorithm"] = o.algorithm;
    j["instances"] = master.instance_names().size();
    j["steps"] = master.steps();
    j["end_time_s"] = master.time_s();
    if (eP) {
      j["eP"] = master.value(*eP);
      j["completion_step"] = complete_at ? json_io::Json(*complete_at) : json_io::Json(nullptr);
    }
    if (monitor.active()) {
      j["handshake"] = violated ? "violated" : "held";
      j["stale_acceptances"] = monitor.stale_count();
    }
    fmt::print("{}\n", json_io::dump_text(j));
  } else {
    fmt::print("cosim {}: {} instances, {} steps of {} s ({}), t = {} s\n", o.multimodel, master.instance_names().size(),
               master.steps(), config.step_s, o.algorithm, master.time_s());
    if (eP)
      fmt::print("eP {:.1f} %{}\n", master.value(*eP),
                 complete_at ? fmt::format(", complete at step {}", *complete_at) : std::string(", not complete"));
    if (monitor.active() && !violated) fmt::print("handshake held: every acceptance was of a fresh waypoint\n");
    if (violated) {
      const auto& first = monitor.stale().front();
      fmt::print("handshake VIOLATED (fresh-acceptance): {} stale acceptances; first: {} accepted its waypoint #{} at "
                 "step {} (t = {} s) with only {} plans made (see `swarmcheck prove`, handshake-gauss-seidel)\n",
                 monitor.stale_count(), first.controller, first.accepted, first.step, first.time_s, first.plans);
    }
    if (csv) fmt::print("wrote {} ({} columns)\n", o.output, master.recorded_names().size() + 2);
  }
  return violated ? 1 : 0;
}

int cosim(const CosimOptions& o) {
  try {
    return run_cosim(o);
  } catch (const swarmcheck::fmi::master::CallTimeout& e) {
    // Thrown out of the run: its master is gone, every instance freed and every folder removed.
    fmt::print(stderr, "swarmcheck cosim: {} (--step-timeout): run stopped, FMUs freed{}\n", e.what(),
               o.output.empty() ? std::string() : ", " + o.output + " not written");
    return 1;
  }
}

}  // namespace

void add_cosim_verb(CLI::App& app, int& exit_code) {
  auto opts = std::make_shared<CosimOptions>();
  CLI::App* cmd = app.add_subcommand(
      "cosim", "Run an INTO-CPS multi-model of FMI 2.0 FMUs (fixed step) as the INTO-CPS engine does: start values "
               "written before initialisation, time by repeated addition, the engine's outputs.csv");
  cmd->add_option("multimodel", opts->multimodel, "The multi-model (JSON: fmus, connections, parameters)")->required();
  cmd->add_option("--config", opts->config,
                  "Co-simulation configuration, as the INTO-CPS application writes it (coe.json: startTime, endTime, "
                  "algorithm {type fixed-step, size}, logVariables, ...); default 0 to 10 s by 0.1 s");
  cmd->add_option("--algorithm", opts->algorithm, "jacobi (every input from the outputs of the step before) | gauss-seidel")
      ->check(CLI::IsMember({"jacobi", "gauss-seidel"}))
      ->capture_default_str();
  cmd->add_option("-o,--output", opts->output,
                  "Write outputs.csv as the INTO-CPS engine does (time, step-size, then every connected output and "
                  "logVariables entry, sorted; time by repeated addition, t += size, as the engine)");
  cmd->add_option("--step-timeout", opts->step_timeout_s,
                  "Stop the run (status 1) when an FMU call (a step, initialisation) has not returned after this "
                  "many seconds, naming the instance and the step; 0: no limit")
      ->check(CLI::Range(0.0, 1e9))
      ->capture_default_str();
  cmd->add_flag("--json", opts->json, "Print the summary as one JSON object");
  cmd->callback([opts, &exit_code] { exit_code = guarded([&] { return cosim(*opts); }); });
}

}  // namespace swarmcheck::cli
