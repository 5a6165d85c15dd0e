#pragma once
// For the tests that differentiate along a link's rotation: the state's axis u turned by a rotation
// vector and the twist sigma moved with it, as the kinematics have it (kinematics.cpp:
// sigma' = -w.(e_z + u)/(1 + u_z)). Written here, not taken from the core, so that the tests' linearized
// equations do not lean on the code they check.
#include <Eigen/Core>
#include <Eigen/Geometry>

/// sigma' for a link of axis u turning at omega [rad/s].
inline double twistRate(const Eigen::Vector3d& omega, const Eigen::Vector3d& axis) {
  const Eigen::Vector3d down = Eigen::Vector3d::UnitZ();
  const double denominator = 1.0 + axis.z();
  return denominator > 1e-12 ? -omega.dot(down + axis) / denominator : -omega.dot(axis);
}

/// u turned by the rotation vector `turn` [rad].
inline Eigen::Vector3d turned(const Eigen::Vector3d& u, const Eigen::Vector3d& turn) {
  const double angle = turn.norm();
  return angle == 0.0 ? u : Eigen::AngleAxisd(angle, turn / angle) * u;
}
