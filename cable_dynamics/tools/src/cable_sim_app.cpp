#include "cable_dynamics/tools/cable_sim_app.h"

#include <algorithm>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <iomanip>
#include <sys/stat.h>

#include "cable_dynamics/simulation/cable_simulator.h"
#include "cable_dynamics/simulation/stable_step.h"
#include "cable_dynamics/tools/cli_options.h"
#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/tools/csv_output.h"

namespace cable_dynamics {
namespace {

/// A run in which more than this fraction of the steps needed substeps exits with status 5.
constexpr double kMaxRetriedFraction = 0.01;
/// A run whose energy balance drifts by more than this fraction of its scale exits with status 5.
constexpr double kMaxEnergyDrift = 1e-3;
/// The same for a scheme judged at the samples (the implicit one), whose balance closes to second order,
/// not to RK4's fourth: a rise beyond this fraction of the scale exits with status 5. Measured with
/// `--sample 0.01` over the presets' runs at their steps: 2.9e-7 (armoured umbilical) and 2.0e-4 (soft
/// tether) of the scale, 1.8e-3 for the TMS tether at 10 ms (its ROV's stiff coupling damper: the work's
/// second-order error, 4.2e-4 at 5 ms; its link ends within 0.8 mm of RK4's); an undamped kinked
/// release at four times its recommended step, whose first steps put in 13 J: 3.6e-2
/// (test_unreliable_runs.py).
constexpr double kMaxSampledRise = 1e-2;

/// The energy balance (mechanical energy + dissipated - work input) over the samples of a run, against
/// its scale (the largest |kinetic| + |potential| + elastic seen) [-].
class SampledBalance {
 public:
  explicit SampledBalance(const SimulationSnapshot& start) : start_(start.total_energy) { add(start); }
  void add(const SimulationSnapshot& s) {
    scale_ = std::max(scale_, std::abs(s.chain.kinetic_energy) + std::abs(s.chain.potential_energy) +
                                  std::abs(s.chain.elastic_energy));
    highest_ = std::max(highest_, s.total_energy - start_);
    lowest_ = std::min(lowest_, s.total_energy - start_);
  }
  double scale() const { return scale_; }
  double rise() const { return scale_ > 0.0 ? highest_ / scale_ : 0.0; }
  double fall() const { return scale_ > 0.0 ? -lowest_ / scale_ : 0.0; }

 private:
  double start_, scale_ = 0.0, highest_ = 0.0, lowest_ = 0.0;  ///< [J]
};

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
  if (o.statics) return writeStatics(*simulator, params, o.output, err);
  CableSimulator& sim = *simulator;
  const StableStep stable = estimateStableStep(params, sim.properties());
  err << "cable_sim: " << params.links << " links, " << integratorName(params.simulation.integrator) << ", dt = " << sim.dt()
      << " s, recommended RK4 step " << stable.recommended << " s (half its estimated stability limit "
      << stable.limit << " s; " << stable.mode << ")";
  if (params.simulation.integrator == Integrator::kImplicit) {
    err << "; implicit: recommended dt " << stable.implicit_recommended << " s (" << stable.implicit_mode << ")"
        << (sim.dt() > stable.implicit_recommended ? "  (dt is larger: less accurate, still stable)" : "") << "\n";
  } else {
    err << (sim.dt() > stable.recommended ? "  (dt is larger: expect substeps)" : "") << "\n";
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
  SimulationSnapshot snapshot;
  sim.snapshot(snapshot);
  writer.writeRow(snapshot);
  if (recorder && !recorder->record(sim, record_error)) {
    err << "cable_sim: " << o.bag << ": " << record_error << "\n";
    return 4;
  }
  const double duration = o.duration ? *o.duration : params.simulation.duration;
  const long steps = std::lround(duration / sim.dt());
  const long every = std::max(1L, std::lround(sample / sim.dt()));
  ProgressBar progress(err, duration);
  long retried = 0;
  int status = 0;
  // Samples in which something sank into the seabed deeper than seabed.penetration allows.
  long sunk = 0;
  // A scheme whose step is not judged by the energy balance (the implicit one: it closes to second order,
  // not to round-off) is judged at the samples: its balance may fall (numerical damping of the fast
  // modes, below rho_inf = 1), but a rise is energy the step put in.
  SampledBalance balance(snapshot);
  double deepest = snapshot.chain.seabed.max_penetration;
  for (long i = 1; i <= steps; ++i) {
    const StepReport report = sim.step();
    if (!report.ok) {
      progress.finish(sim.time());
      err << "cable_sim: " << report.message << "\n";
      status = 3;
      break;
    }
    if (report.substeps > 1) ++retried;
    if (i % every == 0 || i == steps) {
      sim.snapshot(snapshot);
      deepest = std::max(deepest, snapshot.chain.seabed.max_penetration);
      balance.add(snapshot);
      if (params.seabed.enabled && snapshot.chain.seabed.max_penetration > params.seabed.penetration) ++sunk;
      if (!writer.writeRow(snapshot)) {
        err << "cable_sim: non-finite output at t = " << sim.time() << " s; stopped\n";
        status = 3;
        break;
      }
      if (recorder && !recorder->record(sim, record_error)) {
        err << "cable_sim: " << o.bag << ": " << record_error << " at t = " << sim.time() << " s; stopped\n";
        status = 4;
        break;
      }
    }
    progress.update(sim.time());
  }
  if (status == 0) progress.finish(sim.time());
  if (!writer.flush()) {
    err << "cable_sim: cannot write " << o.output << "\n";
    if (status == 0) status = 4;
  }
  csv.close();
  if (recorder && !recorder->close(record_error)) {
    err << "cable_sim: " << o.bag << ": " << record_error << "\n";
    if (status == 0) status = 4;
  }
  if (retried > 0) err << "cable_sim: " << retried << " steps needed substeps after diverging at dt\n";
  // A run whose steps mostly had to be redone in pieces is not the run the configuration asked for.
  const long done = std::lround(sim.time() / sim.dt());
  if (status == 0 && done > 0 && retried > kMaxRetriedFraction * done) {
    err << "cable_sim: " << retried << " of " << done << " steps (more than " << 100 * kMaxRetriedFraction
        << " %) needed substeps: the result is not reliable at dt = " << sim.dt() << " s; use dt <= "
        << stable.recommended << " s or simulation.integrator: implicit (dt " << stable.implicit_recommended << " s)\n";
    status = 5;
  }
  // The energy balance holds to RK4's error (presets: at most 4e-5 of the energy scale over a run, the
  // free fall in air); a drift of more than kMaxEnergyDrift is an unstable mode let through step by step.
  if (status == 0 && sim.energyDrift() > kMaxEnergyDrift) {
    err << "cable_sim: the energy balance drifted by " << sim.energyDrift() << " of its scale (more than "
        << kMaxEnergyDrift << "): the result is not reliable at dt = " << sim.dt() << " s\n";
    status = 5;
  }
  if (sim.energyDrift() < 0.0) {
    err << "cable_sim: energy balance at the samples: rose at most " << balance.rise() << " and fell at most "
        << balance.fall() << " of its scale " << balance.scale() << " J; at every step: rose at most "
        << sim.energyRise() << "\n";
    // Judged at every step (the simulator follows the balance step by step), so that no sampling hides a
    // rise: a run sampled every 0.5 s once passed where one sampled every 10 ms exited 5.
    if (status == 0 && std::max(balance.rise(), sim.energyRise()) > kMaxSampledRise) {
      err << "cable_sim: the energy balance rose by " << std::max(balance.rise(), sim.energyRise()) << " of its scale (more than " << kMaxSampledRise
          << "): the step put energy in; the result is not reliable at dt = " << sim.dt() << " s (recommended "
          << stable.implicit_recommended << " s)\n";
      status = 5;
    }
  }
  if (params.seabed.enabled) {
    err << "cable_sim: deepest penetration into the seabed " << deepest << " m (allowed " << params.seabed.penetration << " m)\n";
  }
  if (status == 0 && sunk > 0) {
    err << "cable_sim: in " << sunk << " samples the cable or the load sank deeper into the seabed than seabed.penetration = "
        << params.seabed.penetration << " m (deepest " << deepest << " m): raise seabed.stiffness or the penetration\n";
    status = 5;
  }
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
