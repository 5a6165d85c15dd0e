#pragma once
/// \file
/// \brief The two frames: world (REP-103, z up) and the paper's frame (z down), related by a half turn
///        about x. Both have their origin at the cable's base (at rest). And the cross-product matrix.
///        The simulator computes and reports in the paper frame (its snapshot too); adapters that publish
///        to the world frame (the node) convert with the functions below, at their boundary.

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace cable_dynamics {

/// Vector or point from the world frame (z up) to the paper frame (z down): (x, -y, -z).
inline Eigen::Vector3d worldToPaper(const Eigen::Vector3d& v) { return {v.x(), -v.y(), -v.z()}; }

/// Vector or point from the paper frame to the world frame; the map is its own inverse.
inline Eigen::Vector3d paperToWorld(const Eigen::Vector3d& v) { return {v.x(), -v.y(), -v.z()}; }

/// An attitude (the frame's rotation from a body's axes) from the paper frame to the world frame: the half
/// turn about x after it. Body-axes quantities are the same in both.
inline Eigen::Quaterniond paperToWorldAttitude(const Eigen::Quaterniond& paper_from_body) {
  return Eigen::Quaterniond(0.0, 1.0, 0.0, 0.0) * paper_from_body;
}

/// An attitude from the world frame to the paper frame: the inverse half turn, so that the round trip
/// gives back the same quaternion, sign included (the products with 0 and +-1 are exact).
inline Eigen::Quaterniond worldToPaperAttitude(const Eigen::Quaterniond& world_from_body) {
  return Eigen::Quaterniond(0.0, -1.0, 0.0, 0.0) * world_from_body;
}

/// A 6x6 map from a motion [linear; angular] to a wrench [force; moment] (a stiffness or a damping), from
/// paper axes to world axes on both sides: T m T with T = diag(1, -1, -1, 1, -1, -1).
inline Eigen::Matrix<double, 6, 6> paperToWorldMap(const Eigen::Matrix<double, 6, 6>& paper) {
  Eigen::Matrix<double, 6, 1> t;
  t << 1.0, -1.0, -1.0, 1.0, -1.0, -1.0;
  return t.asDiagonal() * paper * t.asDiagonal();
}

/// The cross-product matrix S(a) = [a]x: S(a) b = a x b, in any frame.
inline Eigen::Matrix3d crossMatrix(const Eigen::Vector3d& a) {
  Eigen::Matrix3d s;
  s << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return s;
}

}  // namespace cable_dynamics
