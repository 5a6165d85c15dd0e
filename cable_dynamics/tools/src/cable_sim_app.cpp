#include "cable_dynamics/tools/cable_sim_app.h"

#include <algorithm>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <iomanip>
#include <sstream>
#include <sys/stat.h>

#include "cable_dynamics/simulation/cable_simulator.h"
#include "cable_dynamics/simulation/stable_step.h"
#include "cable_dynamics/tools/cli_options.h"
#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/tools/csv_output.h"
#include "cable_dynamics/tools/sampled_run.h"

namespace cable_dynamics {
namespace {

const char* const kUsage =
    "usage: cable_sim --config FILE [--set key.path=value ...] [--duration S] --output run.csv\n"
    "                 [--plot run.png] [--bag run.bag] [--sample S] [--statics]\n"
    "Simulates the cable offline and writes one CSV row every --sample seconds (default 0.01 s).\n"
    "--bag also writes the node's topics at those instants as a rosbag (rosbag play, rviz).\n"
    "--duration defaults to the config's simulation.duration.\n"
    "--statics solves the static equilibrium for the configured loads and ends instead, writes it as the\n"
    "CSV's one row (t = 0) and exits (status 6 when there is none, with the reason).\n";

bool fileExists(const std::string& path) {
  struct stat info;
  return stat(path.c_str(), &info) == 0;
}

/// The plotting script: next to the sources in a devel build, under share/ when installed.
std::string plotScript() {
  for (const char* candidate : {CABLE_SOURCE_PLOT_SCRIPT, CABLE_INSTALLED_PLOT_SCRIPT}) {
    if (fileExists(candidate)) return candidate;
  }
  return CABLE_SOURCE_PLOT_SCRIPT;
}

/// A one-line progress bar on a terminal, rewritten in place at most every 0.1 s of wall time.
class ProgressBar {
 public:
  ProgressBar(std::ostream& err, double duration) : err_(err), duration_(duration), enabled_(isatty(STDERR_FILENO)) {}
  void update(double t, bool force = false) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (!force && now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    const double fraction = std::min(1.0, t / duration_);
    const int width = 40, filled = static_cast<int>(fraction * width);
    const double wall = std::chrono::duration<double>(now - start_).count();
    err_ << "\r[" << std::string(filled, '#') << std::string(width - filled, ' ') << "] " << std::setw(3)
         << static_cast<int>(100 * fraction) << "%  t = " << std::fixed << std::setprecision(2) << t << " s  x"
         << std::setprecision(1) << (wall > 0 ? t / wall : 0.0) << " real time" << std::defaultfloat << std::flush;
  }
  void finish(double t) {
    update(t, true);
    if (enabled_) err_ << "\n";
  }

 private:
  std::ostream& err_;
  double duration_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now(), last_{};
};

/// cable_sim --statics: the equilibrium as the CSV's one row, a summary on `err`. Exit status 0, 4 (cannot
/// write), 6 (no equilibrium).
int writeStatics(CableSimulator& sim, const CableParams& params, const std::string& output, std::ostream& err) {
  const auto start = std::chrono::steady_clock::now();
  const StaticSolution s = sim.resetToEquilibrium();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!s.converged) {
    err << "cable_sim: no static equilibrium: " << s.message << "\n";
    return 6;
  }
  std::ofstream csv(output);
  if (!csv) {
    err << "cable_sim: cannot write " << output << "\n";
    return 4;
  }
  SimulationSnapshot snapshot;
  sim.snapshot(snapshot);
  CsvWriter writer(csv, params.links, CsvWriter::kDefaultFlushBytes, params.seabed.enabled, params.stretches());
  writer.writeHeader();
  if (!writer.writeRow(snapshot)) {
    err << "cable_sim: the static equilibrium has a non-finite value\n";
    return 3;
  }
  if (!writer.flush()) {
    err << "cable_sim: cannot write " << output << "\n";
    return 4;
  }
  err << "cable_sim: static equilibrium in " << s.iterations << " Newton iterations, residual " << s.residual
      << " (tolerance " << StaticOptions{}.tolerance << "), " << 1e3 * wall << " ms; top tension "
      << snapshot.line_pull << " N; wrote " << output << "\n";
  return 0;
}

}  // namespace

int runCableSim(int argc, const char* const* argv, std::ostream& out, std::ostream& err,
                const SampleRecorderFactory& bag) {
  CliOptions o;
  CableParams params;
  double sample = 0.01;
  try {
    o = parseCli(argc, argv,
                 {"--config", "--set", "--duration", "--output", "--plot", "--bag", "--sample", "--statics"});
    if (o.help) {
      out << kUsage;
      return 0;
    }
    if (o.config.empty()) throw UsageError("--config FILE is required");
    if (o.output.empty()) throw UsageError("--output run.csv is required");
    if (!o.bag.empty() && !bag) throw UsageError("--bag: this build of cable_sim has no rosbag output");
    if (!o.bag.empty() && o.statics) throw UsageError("--bag is for a run, not for --statics");
    if (o.sample) sample = *o.sample;
    params = loadConfigFile(o.config, o.overrides);
  } catch (const UsageError& e) {
    err << "cable_sim: " << e.what() << "\n" << kUsage;
    return 2;
  } catch (const ConfigError& e) {
    err << "cable_sim: " << e.what() << "\n";
    return 2;
  }

  if (o.statics) params.initial.mode = InitialMode::kAngles;  // solved below, with its report
  std::unique_ptr<CableSimulator> simulator;
  try {
    // The gate (checkSimulatorInputs): a dt beyond RK4's reach is refused, unless only the statics run.
    simulator = std::make_unique<CableSimulator>(params, o.statics ? SimulatorUse::kStaticsOnly : SimulatorUse::kStepping);
  } catch (const std::invalid_argument& e) {
    err << "cable_sim: " << e.what() << "\n";
    return 2;
  } catch (const std::runtime_error& e) {  // initial.mode: equilibrium without an equilibrium
    err << "cable_sim: " << e.what() << "\n";
    return 6;
  }
  params = simulator->params();  // the model's copy: with a winch, the drum's slots the CSV has columns for
  if (o.statics) return writeStatics(*simulator, params, o.output, err);
  CableSimulator& sim = *simulator;
  const StableStep stable = estimateStableStep(params, sim.properties());
  err << "cable_sim: " << params.links << " links, " << integratorName(params.simulation.integrator) << ", dt = " << sim.dt()
      << " s, recommended RK4 step " << stable.recommended << " s (";
  if (stable.whip < stable.limit / 2.0) err << "for accuracy, " << stable.whip_mode << "; its estimated stability limit ";
  else err << "half its estimated stability limit ";
  err << stable.limit << " s; " << stable.mode << ")";
  if (params.simulation.integrator == Integrator::kImplicit) {
    err << "; implicit: recommended dt " << stable.implicit_recommended << " s (" << stable.implicit_mode << ")"
        << (aboveShownStep(sim.dt(), stable.implicit_recommended) ? "  (dt is larger: less accurate, still stable)" : "") << "\n";
  } else {
    const bool above = aboveShownStep(sim.dt(), stable.recommended);
    const bool past_whip = above && sim.dt() <= stable.limit / 2.0;
    err << (past_whip ? "  (dt is larger: steps may be retried where the chain whips)"
                      : above ? "  (dt is larger: expect substeps)" : "")
        << "\n";
  }

  std::ofstream csv(o.output);
  if (!csv) {
    err << "cable_sim: cannot write " << o.output << "\n";
    return 4;
  }
  std::unique_ptr<SampleRecorder> recorder;
  if (!o.bag.empty()) {
    try {
      recorder = bag(o.bag, params);
    } catch (const std::runtime_error& e) {
      err << "cable_sim: " << e.what() << "\n";
      return 4;
    }
  }
  std::string record_error;
  CsvWriter writer(csv, params.links, CsvWriter::kDefaultFlushBytes, params.seabed.enabled, params.stretches());
  writer.writeHeader();
  const double duration = o.duration ? *o.duration : params.simulation.duration;
  ProgressBar progress(err, duration);
  // The steps, the samples and the verdict: tools/sampled_run.h (the Python module's Simulator.run too).
  SampledRun run(sim, params);
  std::string error;
  int status = run.run(
      duration, sample,
      [&](const SimulationSnapshot& snapshot, std::string& why) {
        if (!writer.writeRow(snapshot)) {
          why = nonFiniteOutputReason(snapshot.time);
          return 3;
        }
        if (recorder && !recorder->record(sim, record_error)) {
          std::ostringstream message;
          message << o.bag << ": " << record_error;
          if (snapshot.time > 0.0) message << " at t = " << snapshot.time << " s; stopped";
          why = message.str();
          return 4;
        }
        return 0;
      },
      [&](double t) { progress.update(t); }, error);
  progress.finish(sim.time());
  if (status != 0) err << "cable_sim: " << error << "\n";
  if (!writer.flush()) {
    err << "cable_sim: cannot write " << o.output << "\n";
    if (status == 0) status = 4;
  }
  csv.close();
  if (recorder && !recorder->close(record_error)) {
    err << "cable_sim: " << o.bag << ": " << record_error << "\n";
    if (status == 0) status = 4;
  }
  std::vector<std::string> report;
  status = run.judge(status, report);
  for (const std::string& line : report) err << "cable_sim: " << line << "\n";
  err << "cable_sim: wrote " << o.output << (recorder ? " and " + o.bag : std::string()) << " (t = 0 to "
      << sim.time() << " s)\n";

  if (!o.plot.empty()) {
    const std::string command = "/usr/bin/python3 '" + plotScript() + "' '" + o.output + "' '" + o.plot + "'";
    if (std::system(command.c_str()) != 0) {
      err << "cable_sim: plotting failed: " << command << "\n";
      return status != 0 ? status : 4;
    }
    err << "cable_sim: wrote " << o.plot << "\n";
  }
  return status;
}

}  // namespace cable_dynamics
