#pragma once
/// \file
/// \brief The two frames: world (REP-103, z up) and the paper's frame (z down), related by a half turn
///        about x. Both have their origin at the cable's base (at rest). And the cross-product matrix.

#include <Eigen/Core>

namespace cable_dynamics {

/// Vector or point from the world frame (z up) to the paper frame (z down): (x, -y, -z).
inline Eigen::Vector3d worldToPaper(const Eigen::Vector3d& v) { return {v.x(), -v.y(), -v.z()}; }

/// Vector or point from the paper frame to the world frame; the map is its own inverse.
inline Eigen::Vector3d paperToWorld(const Eigen::Vector3d& v) { return {v.x(), -v.y(), -v.z()}; }

/// The cross-product matrix S(a) = [a]x: S(a) b = a x b, in any frame.
inline Eigen::Matrix3d crossMatrix(const Eigen::Vector3d& a) {
  Eigen::Matrix3d s;
  s << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return s;
}

}  // namespace cable_dynamics
