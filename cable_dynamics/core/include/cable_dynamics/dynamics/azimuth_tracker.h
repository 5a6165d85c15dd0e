#pragma once
/// \file
/// \brief Keeps each link's azimuth continuous (unwrapped) as the cable moves, with no trigonometry per step.

#include <Eigen/Core>

namespace cable_dynamics {

/// The paper's azimuth of a link is psi = atan2(u_x, u_y) + 2 pi w: the angle of its horizontal direction
/// plus a whole number of turns w. The tracker stores the last horizontal direction seen and w, and
/// counts a turn whenever the shorter arc from the last direction to the new one crosses the branch
/// cut of atan2 (u_x = 0, u_y < 0). That is the nearest-branch unwrapping psi += wrap(atan2 - psi),
/// at the cost of a few comparisons instead of three transcendental functions per link and step.
class AzimuthTracker {
 public:
  explicit AzimuthTracker(int links);

  /// Starts from the unwrapped azimuths psi (size links) [rad].
  void reset(const Eigen::VectorXd& psi);

  /// Link k's horizontal direction is now (x, y) (any length > 0; the caller skips vertical links).
  void follow(int k, double x, double y);

  /// Link `to` continues from link `from`'s azimuth (a link split in two at the winch).
  void copy(int from, int to) {
    direction_.col(to) = direction_.col(from);
    turns_(to) = turns_(from);
  }

  /// Unwrapped azimuth of link k at the last direction followed [rad].
  double reference(int k) const;

 private:
  Eigen::Matrix2Xd direction_;  ///< (2 x n) last horizontal direction (x, y), any scale
  Eigen::VectorXi turns_;       ///< (n) whole turns w
};

}  // namespace cable_dynamics
