#pragma once
/// \file
/// \brief cable_sim's run, written once: the steps, the sample instants (t = 0, then every `sample`
///        seconds and the last step) and the judgment of the finished run (exit status 5: too many retried
///        steps, the energy balance, the seabed's penetration). cable_sim and the Python module's
///        Simulator.run (which cable_sweep uses) both run through it, so a sweep's case and a direct
///        cable_sim run of it see the same samples and the same verdict.

#include <functional>
#include <string>
#include <vector>

#include "cable_dynamics/params/cable_params.h"
#include "cable_dynamics/simulation/cable_simulator.h"

namespace cable_dynamics {

/// Called at every sample instant with the simulator's snapshot there. Returns 0 to go on, or the status
/// that stops the run (3: a non-finite output, 4: an output could not be written) with the reason in
/// `error`.
using SampleHandler = std::function<int(const SimulationSnapshot& snapshot, std::string& error)>;

/// The reason a run stops at a sample with a non-finite output (status 3), as cable_sim prints it: one
/// text for cable_sim and Simulator.run, so a sweep's row and a direct run give the same reason.
std::string nonFiniteOutputReason(double time);

/// One run of a simulator from its present instant (as cable_sim does it).
class SampledRun {
 public:
  /// A run in which more than this fraction of the steps needed substeps is not reliable (status 5).
  static constexpr double kMaxRetriedFraction = 0.01;
  /// A run (RK4) whose energy balance drifts by more than this fraction of its scale is not reliable.
  static constexpr double kMaxEnergyDrift = 1e-3;
  /// The same for a scheme judged at the samples (the implicit one), whose balance closes to second order,
  /// not to RK4's fourth: a rise beyond this fraction of the scale is not reliable. Measured with
  /// `--sample 0.01` over the presets' runs at their steps: 2.9e-7 (armoured umbilical) and 2.0e-4 (soft
  /// tether) of the scale, 1.8e-3 for the TMS tether at 10 ms (its ROV's stiff coupling damper: the work's
  /// second-order error, 4.2e-4 at 5 ms; its link ends within 0.8 mm of RK4's); an undamped kinked
  /// release at four times its recommended step, whose first steps put in 13 J: 3.6e-2
  /// (test_unreliable_runs.py).
  static constexpr double kMaxSampledRise = 1e-2;

  SampledRun(CableSimulator& sim, const CableParams& params) : sim_(sim), params_(params) {}

  /// Steps round(duration / dt) steps of dt, calling `on_sample` at the present instant first, then after
  /// every round(sample / dt)-th step and after the last one; `on_step` (may be empty) after every step
  /// with the simulated time [s]. Returns 0 when every step was taken, 3 when a step failed even in
  /// substeps (its message in `error`; the state stays at the last good step), or the status
  /// `on_sample` stopped it with.
  int run(double duration, double sample, const SampleHandler& on_sample, const std::function<void(double)>& on_step,
          std::string& error);

  /// cable_sim's judgment of the run: appends the lines it prints after a run to `lines` (the substeps
  /// taken, the implicit scheme's balance, the seabed's deepest penetration, and the reason the run is
  /// not reliable, if it is not and `status` is 0). Returns 5 when `status` is 0 and the run is not
  /// reliable, else `status`. `unreliable`, when not null, gets that reason (empty when reliable).
  int judge(int status, std::vector<std::string>& lines, std::string* unreliable = nullptr) const;

 private:
  CableSimulator& sim_;
  const CableParams& params_;
  long retried_ = 0;  ///< steps that needed substeps
  long sunk_ = 0;     ///< samples in which something sank deeper into the seabed than allowed
  double deepest_ = 0.0;  ///< deepest penetration seen at a sample [m]
  // The energy balance (mechanical energy + dissipated - work input) at the samples [J].
  double balance_start_ = 0.0, balance_scale_ = 0.0, balance_highest_ = 0.0, balance_lowest_ = 0.0;
  void addSample(const SimulationSnapshot& s);
  double rise() const { return balance_scale_ > 0.0 ? balance_highest_ / balance_scale_ : 0.0; }
  double fall() const { return balance_scale_ > 0.0 ? -balance_lowest_ / balance_scale_ : 0.0; }
};

}  // namespace cable_dynamics
