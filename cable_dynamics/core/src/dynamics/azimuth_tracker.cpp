#include "cable_dynamics/dynamics/azimuth_tracker.h"

#include <cmath>

namespace cable_dynamics {

AzimuthTracker::AzimuthTracker(int links) : direction_(2, links), turns_(links) {
  reset(Eigen::VectorXd::Zero(links));
}

void AzimuthTracker::reset(const Eigen::VectorXd& psi) {
  for (int k = 0; k < psi.size(); ++k) {
    direction_.col(k) << std::sin(psi(k)), std::cos(psi(k));
    const double principal = std::atan2(direction_(0, k), direction_(1, k));
    turns_(k) = static_cast<int>(std::lround((psi(k) - principal) / (2.0 * M_PI)));
  }
}

void AzimuthTracker::follow(int k, double x, double y) {
  const double old_x = direction_(0, k), old_y = direction_(1, k);
  // atan2(x, y) lies in [0, pi] when x is +0 or positive and in [-pi, 0) when x is -0 or negative; the
  // sign bit is what atan2 itself looks at on the cut. `turning` > 0 when psi increases along the
  // shorter arc (it is |old| |new| sin(psi_new - psi_old)).
  const bool was_east = !std::signbit(old_x), is_east = !std::signbit(x);
  const double turning = x * old_y - y * old_x;
  if (was_east && !is_east && turning > 0.0) {
    ++turns_(k);  // through +pi, increasing
  } else if (!was_east && is_east && turning < 0.0) {
    --turns_(k);  // through -pi, decreasing
  }
  direction_(0, k) = x;
  direction_(1, k) = y;
}

double AzimuthTracker::reference(int k) const {
  return std::atan2(direction_(0, k), direction_(1, k)) + 2.0 * M_PI * turns_(k);
}

}  // namespace cable_dynamics
