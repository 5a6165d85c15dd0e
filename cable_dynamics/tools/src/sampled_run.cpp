#include "cable_dynamics/tools/sampled_run.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cable_dynamics/simulation/stable_step.h"

namespace cable_dynamics {

std::string nonFiniteOutputReason(double time) {
  std::ostringstream message;
  message << "non-finite output at t = " << time << " s; stopped";
  return message.str();
}

void SampledRun::addSample(const SimulationSnapshot& s) {
  balance_scale_ = std::max(balance_scale_, std::abs(s.chain.kinetic_energy) + std::abs(s.chain.potential_energy) +
                                                std::abs(s.chain.elastic_energy));
  balance_highest_ = std::max(balance_highest_, s.total_energy - balance_start_);
  balance_lowest_ = std::min(balance_lowest_, s.total_energy - balance_start_);
  deepest_ = std::max(deepest_, s.chain.seabed.max_penetration);
}

int SampledRun::run(double duration, double sample, const SampleHandler& on_sample,
                    const std::function<void(double)>& on_step, std::string& error) {
  SimulationSnapshot snapshot;
  sim_.snapshot(snapshot);
  // A scheme whose step is not judged by the energy balance (the implicit one: it closes to second order,
  // not to round-off) is judged at the samples: its balance may fall (numerical damping of the fast
  // modes, below rho_inf = 1), but a rise is energy the step put in.
  balance_start_ = snapshot.total_energy;
  addSample(snapshot);
  if (const int status = on_sample(snapshot, error)) return status;
  const long steps = std::lround(duration / sim_.dt());
  const long every = std::max(1L, std::lround(sample / sim_.dt()));
  for (long i = 1; i <= steps; ++i) {
    const StepReport report = sim_.step();
    if (!report.ok) {
      error = report.message;
      return 3;
    }
    if (report.substeps > 1) ++retried_;
    if (i % every == 0 || i == steps) {
      sim_.snapshot(snapshot);
      addSample(snapshot);
      if (params_.seabed.enabled && snapshot.chain.seabed.max_penetration > params_.seabed.penetration) ++sunk_;
      if (const int status = on_sample(snapshot, error)) return status;
    }
    if (on_step) on_step(sim_.time());
  }
  return 0;
}

int SampledRun::judge(int status, std::vector<std::string>& lines, std::string* unreliable) const {
  const StableStep stable = estimateStableStep(params_, sim_.properties());
  // Each line is built as `std::ostringstream() << ...`: a reference to the temporary ostringstream.
  const auto text = [](const std::ostream& line) { return static_cast<const std::ostringstream&>(line).str(); };
  const auto say = [&](const std::ostream& line) { lines.push_back(text(line)); };
  const auto fail = [&](const std::ostream& line) {
    lines.push_back(text(line));
    if (unreliable) *unreliable = lines.back();
    status = 5;
  };
  if (unreliable) unreliable->clear();
  if (retried_ > 0) say(std::ostringstream() << retried_ << " steps needed substeps after diverging at dt");
  // A run whose steps mostly had to be redone in pieces is not the run the configuration asked for.
  const long done = std::lround(sim_.time() / sim_.dt());
  if (status == 0 && done > 0 && retried_ > kMaxRetriedFraction * done) {
    std::ostringstream line;
    line << retried_ << " of " << done << " steps (more than " << 100 * kMaxRetriedFraction
         << " %) needed substeps: the result is not reliable at dt = " << sim_.dt() << " s; ";
    if (params_.simulation.integrator == Integrator::kImplicit) {
      // The implicit step is retried where the balance rose by more than 2e-3 of its scale in one step: an
      // event within it (a point landing on the bed's stiff spring) or a mode it cannot hold at this dt.
      line << "the energy balance rose in too many single steps (an event within a step, such as a point "
              "landing on the bed, or a mode the step cannot hold at this dt); take a smaller dt (recommended "
           << stable.implicit_recommended << " s)";
    } else if (aboveShownStep(sim_.dt(), stable.recommended)) {
      line << "use dt <= " << stable.recommended << " s or simulation.integrator: implicit (dt "
           << stable.implicit_recommended << " s)";
    } else {
      // At or below the recommendation: the estimate is made from the configured start, and the run went
      // where it does not reach (an ROV 10 m off the tip of a tether in air yanks it at 25000 m/s^2).
      line << "that is within the recommended RK4 step " << stable.recommended
           << " s, which is estimated from the start: the run went beyond the loads and speeds it covers; look "
              "at what drives it, or take a smaller dt";
    }
    fail(line);
  }
  // The energy balance holds to RK4's error (presets: at most 4e-5 of the energy scale over a run, the
  // free fall in air); a drift of more than kMaxEnergyDrift is an unstable mode let through step by step.
  if (status == 0 && sim_.energyDrift() > kMaxEnergyDrift) {
    fail(std::ostringstream() << "the energy balance drifted by " << sim_.energyDrift() << " of its scale (more than "
                              << kMaxEnergyDrift << "): the result is not reliable at dt = " << sim_.dt() << " s");
  }
  if (sim_.energyDrift() < 0.0) {
    say(std::ostringstream() << "energy balance at the samples: rose at most " << rise() << " and fell at most "
                             << fall() << " of its scale " << balance_scale_ << " J; at every step: rose at most "
                             << sim_.energyRise());
    // Judged at every step (the simulator follows the balance step by step), so that no sampling hides a
    // rise: a run sampled every 0.5 s once passed where one sampled every 10 ms exited 5.
    const double rose = std::max(rise(), sim_.energyRise());
    if (status == 0 && rose > kMaxSampledRise) {
      fail(std::ostringstream() << "the energy balance rose by " << rose << " of its scale (more than "
                                << kMaxSampledRise << "): the step put energy in; the result is not reliable at dt = "
                                << sim_.dt() << " s (recommended " << stable.implicit_recommended << " s)");
    }
  }
  if (params_.seabed.enabled) {
    say(std::ostringstream() << "deepest penetration into the seabed " << deepest_ << " m (allowed "
                             << params_.seabed.penetration << " m)");
  }
  if (status == 0 && sunk_ > 0) {
    fail(std::ostringstream() << "in " << sunk_
                              << " samples the cable or the load sank deeper into the seabed than seabed.penetration = "
                              << params_.seabed.penetration << " m (deepest " << deepest_
                              << " m): raise seabed.stiffness or the penetration");
  }
  return status;
}

}  // namespace cable_dynamics
