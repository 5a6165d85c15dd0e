#pragma once
/// \file
/// \brief Small kinematic helpers the integrators and the solvers share: the twist's rate of a turning
///        link (the kinematics' sigma', kinematics.cpp) and the cross-product matrix.

#include <Eigen/Core>

namespace cable_dynamics {

/// sigma' [rad/s] for a link of axis u (paper frame) turning at omega [rad/s]: -omega.(e_z + u)/(1 + u_z),
/// with its limit -omega.u where the link points straight up (1 + u_z -> 0).
inline double twistRate(const Eigen::Vector3d& omega, const Eigen::Vector3d& axis) {
  const double denominator = 1.0 + axis.z();
  return denominator > 1e-12 ? -omega.dot(Eigen::Vector3d::UnitZ() + axis) / denominator : -omega.dot(axis);
}

/// [v]x, the matrix with [v]x w = v x w.
inline Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return s;
}

}  // namespace cable_dynamics
