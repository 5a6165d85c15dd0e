#pragma once
/// \file
/// \brief A symmetric 3x3 matrix stored as its six entries.

#include <Eigen/Core>

namespace cable_dynamics {

/// Symmetric 3x3 matrix [xx xy xz; xy yy yz; xz yz zz], exactly symmetric by construction (the
/// articulated-body recursion amplifies an antisymmetric round-off part link by link, a symmetric one not).
struct Symmetric3 {
  double xx = 0.0, xy = 0.0, xz = 0.0, yy = 0.0, yz = 0.0, zz = 0.0;

  static Symmetric3 scaledIdentity(double s) { return {s, 0.0, 0.0, s, 0.0, s}; }

  Eigen::Vector3d operator*(const Eigen::Vector3d& v) const {
    return {xx * v.x() + xy * v.y() + xz * v.z(), xy * v.x() + yy * v.y() + yz * v.z(),
            xz * v.x() + yz * v.y() + zz * v.z()};
  }
};

}  // namespace cable_dynamics
