#include "cable_dynamics/simulation/step_check.h"

#include <algorithm>
#include <cmath>

#include "cable_dynamics/dynamics/state_layout.h"

namespace cable_dynamics {

EnergyBalance energyBalance(double mechanical_energy, double mechanical_magnitude, const Eigen::VectorXd& x, int n) {
  EnergyBalance b;
  b.dissipated = x(StateLayout::dissipated(n));
  b.work = x(StateLayout::workInput(n));
  b.value = mechanical_energy + b.dissipated - b.work;
  b.mechanical = mechanical_magnitude;
  return b;
}

StepLimits stepLimits(double shortest_link, double gravity) {
  StepLimits limits;
  limits.max_angular_velocity = std::max(1000.0, 1000.0 * std::sqrt(std::max(gravity, 1.0) / shortest_link));
  return limits;
}

bool projectAxes(Eigen::VectorXd& x, int n, int first) {
  for (int k = first; k < n; ++k) {
    auto axis = x.segment<3>(StateLayout::axis(k));
    const double norm = std::sqrt(axis.squaredNorm());
    if (!std::isfinite(norm) || norm < 0.5) return false;
    axis *= 1.0 / norm;
  }
  return true;
}

StepVerdict judgeStep(const Eigen::VectorXd& x, int n, const StepLimits& limits, int first) {
  // One sum: any NaN or infinity shows.
  if (!std::isfinite(x.tail(StateLayout::moving(x.size(), first)).sum())) return StepVerdict::kNotFinite;
  const double limit_squared = limits.max_angular_velocity * limits.max_angular_velocity;
  for (int k = first; k < n; ++k) {
    if (!(x.segment<3>(StateLayout::omega(k)).squaredNorm() < limit_squared)) return StepVerdict::kRunawaySpin;
  }
  return StepVerdict::kAccepted;
}

StepVerdict judgeEnergy(const EnergyBalance& before, const EnergyBalance& after, double tolerance) {
  const double flows = std::abs(after.dissipated - before.dissipated) + std::abs(after.work - before.work);
  const double scale = std::max(before.mechanical, after.mechanical) + flows + 1e-9;
  if (!std::isfinite(after.value)) return StepVerdict::kNotFinite;
  return after.value - before.value > tolerance * scale ? StepVerdict::kEnergyCreated
                                                                       : StepVerdict::kAccepted;
}

const char* verdictName(StepVerdict verdict) {
  switch (verdict) {
    case StepVerdict::kAccepted:
      return "accepted";
    case StepVerdict::kNotFinite:
      return "a non-finite state";
    case StepVerdict::kRunawaySpin:
      return "a runaway angular velocity";
    case StepVerdict::kEnergyCreated:
      return "energy created";
  }
  return "?";
}

}  // namespace cable_dynamics
