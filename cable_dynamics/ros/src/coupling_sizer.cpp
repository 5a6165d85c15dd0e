#include "cable_dynamics/ros/coupling_sizer.h"

#include <algorithm>
#include <cmath>

namespace cable_dynamics {

CouplingSizer::CouplingSizer(double stiffness, double damping, double min_mass, double cycle_period)
    : configured_stiffness_(stiffness),
      configured_damping_(damping),
      min_mass_(min_mass),
      cycle_period_(cycle_period),
      exchange_period_(cycle_period),
      sized_delay_(2.0 * cycle_period) {
  sizeFor(delay(), stiffness_, damping_);
}

void CouplingSizer::sizeFor(double tau, double& stiffness, double& damping) const {
  stiffness = std::min(configured_stiffness_, kSpring * min_mass_ / (tau * tau));
  damping = std::min(configured_damping_, kDamper * min_mass_ / tau);
}

void CouplingSizer::setConfigured(double stiffness, double damping) {
  configured_stiffness_ = stiffness;
  configured_damping_ = damping;
  sized_delay_ = delay();
  sizeFor(sized_delay_, stiffness_, damping_);
}

bool CouplingSizer::observe(const ros::Time& stamp) {
  if (!last_stamp_.isZero()) {
    const double interval = (stamp - last_stamp_).toSec();
    // Intervals outside (0, 1 s] are a restarted or stalled stream, not its rate.
    if (interval > 0.0 && interval <= 1.0) {
      intervals_[count_ % kIntervals] = interval;
      ++count_;
    }
  }
  last_stamp_ = stamp;
  if (count_ < 10) return false;
  std::array<double, kIntervals> sorted = intervals_;
  const int used = std::min(count_, kIntervals);
  const int at = static_cast<int>(kQuantile * (used - 1));
  std::nth_element(sorted.begin(), sorted.begin() + at, sorted.begin() + used);
  exchange_period_ = sorted[at];
  return resize();
}

void CouplingSizer::forgetStream() {
  count_ = 0;
  last_stamp_ = ros::Time();
}

bool CouplingSizer::resize() {
  const double change = delay() / sized_delay_ - 1.0;
  if (change <= kSoften && change >= -kStiffen) return false;
  double k = 0.0, c = 0.0;
  sizeFor(delay(), k, c);
  sized_delay_ = delay();
  const bool changed = k != stiffness_ || c != damping_;  // both may sit at the configured caps
  stiffness_ = k;
  damping_ = c;
  return changed;
}

}  // namespace cable_dynamics
