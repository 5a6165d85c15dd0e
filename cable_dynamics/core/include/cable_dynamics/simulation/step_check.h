#pragma once
/// \file
/// \brief Judging a step: is the state it reached finite, are the links spinning at a believable rate,
///        and (for schemes that balance energy) did it create energy? The judgement changes nothing.

#include <Eigen/Core>

namespace cable_dynamics {

/// Kinetic + potential + elastic + dissipated - work input at one state [J] (constant up to the
/// scheme's error), and the scale the check measures its change against [J].
struct EnergyBalance {
  double value = 0.0;       ///< the balance [J]
  double mechanical = 0.0;  ///< |kinetic| + |potential| + |elastic| [J]
  double dissipated = 0.0;  ///< energy taken out so far [J]
  double work = 0.0;        ///< work put in so far [J]
};

/// The balance of a state from its mechanical energy [J], the sum of its terms' magnitudes [J] and the
/// energy accumulators of x (StateLayout).
EnergyBalance energyBalance(double mechanical_energy, double mechanical_magnitude, const Eigen::VectorXd& x, int links);

/// Why a step was refused.
enum class StepVerdict {
  kAccepted,
  kNotFinite,      ///< a non-finite entry, or an axis of (near) zero length
  kRunawaySpin,    ///< an angular velocity beyond the limit
  kEnergyCreated,  ///< the energy balance grew by more than the tolerance
};

/// Limits of a believable step.
struct StepLimits {
  /// Largest angular velocity of any link [rad/s]: 1000 x the swing rate of the shortest link as a
  /// pendulum, and at least 1000 rad/s (stepLimits()).
  double max_angular_velocity = 1000.0;
  /// Largest growth of the energy balance in one step, relative to its scale [-]. RK4's local error is
  /// ~1e-10 of the scale per step in the presets; an unstable mode shows as energy created.
  double energy_tolerance = 1e-4;
  /// The same for the implicit step, whose balance closes to second order rather than RK4's fourth: the
  /// presets' largest rise in one step at 10 ms is 1.6e-3 of the scale (tms_tether's first step); a point
  /// landing within a step on the bed's stiff spring rose by 0.29 (docs/MODEL.md section 6). Beyond it the
  /// step is retried in pieces, as RK4's are (TimeScheme::riseTolerance).
  double linear_energy_tolerance = 2e-3;
};

/// The limits for a chain whose shortest link is `shortest_link` [m] under gravity g [m/s^2].
StepLimits stepLimits(double shortest_link, double gravity);

/// Links' axes back onto the unit sphere after a step (the schemes step u as three numbers). Returns
/// false, changing nothing further, at an axis that is not finite or shorter than 1/2 (diverged).
bool projectAxes(Eigen::VectorXd& x, int links, int first = 0);

/// The verdict on the state x a step reached; and (judgeEnergy) whether the step created energy: the growth
/// of the balance against tolerance x scale (StepLimits' tolerance for the scheme), with the scale the
/// larger mechanical magnitude of the two states plus what this step dissipated and put in. The scale
/// deliberately leaves out the accumulated dissipated energy and work: they grow with the run, and with
/// any error the run has made, so a tolerance relative to them would loosen as a run goes wrong.
StepVerdict judgeStep(const Eigen::VectorXd& x, int links, const StepLimits& limits, int first = 0);
StepVerdict judgeEnergy(const EnergyBalance& before, const EnergyBalance& after, double tolerance);

/// Text for a verdict ("accepted", "not finite", ...).
const char* verdictName(StepVerdict verdict);

}  // namespace cable_dynamics
