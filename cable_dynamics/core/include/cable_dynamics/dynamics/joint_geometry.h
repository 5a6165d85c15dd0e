#pragma once
/// \file
/// \brief The bending model's geometry of one joint, written once: the bend angle between two link axes
///        and the twist between them after parallel transport (docs/MODEL.md section 5). The dynamics use
///        it on link axes (joint_torques.cpp), ElasticJoints on paper angles with automatic
///        differentiation, hence the scalar template.

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace cable_dynamics {

/// Solid angle Omega of the spherical triangle (down, a, b) for unit vectors a, b (down = +z, paper
/// frame; Van Oosterom and Strackee): the rotation about the vertical that parallel transport from a to
/// b picks up. The twist between neighbours is sigma_b - sigma_a - Omega.
template <typename S>
S transportHolonomy(const S& ax, const S& ay, const S& az, const S& bx, const S& by, const S& bz) {
  using std::atan2;
  const S vertical_triple = ax * by - ay * bx;  // down . (a x b)
  return -2.0 * atan2(vertical_triple, 1.0 + az + bz + (ax * bx + ay * by + az * bz));
}

/// Bend angle squared beta^2 as a smooth function of the chord s = |a - b|^2 = 2 - 2 cos(beta):
/// beta = 2 asin(sqrt(s)/2). The series near s = 0 keeps every derivative finite at a straight joint.
template <typename S>
S bendAngleSquared(const S& chord_squared, double chord_value) {
  using std::asin;
  using std::sqrt;
  const S& s = chord_squared;
  if (chord_value < 1e-4) return s + s * s / 12.0 + s * s * s / 90.0;  // next term s^4/560: < 2e-19 here
  const S beta = 2.0 * asin(sqrt(s) / 2.0);
  return beta * beta;
}

/// beta / sin(beta) for the bend angle beta (the bend spring's torque is k beta/sin(beta) (a x b)), with
/// its series where sin(beta) -> 0.
inline double bendOverSine(double bend, double sine) { return bend < 1e-4 ? 1.0 + bend * bend / 6.0 : bend / sine; }

/// One joint of the bending model between the axes `prev` and `axis` with vertical twists sigma_prev and
/// sigma [rad].
struct JointGeometry {
  Eigen::Vector3d cross;  ///< prev x axis
  double cosine, sine;    ///< of the bend angle
  double bend, twist;     ///< [rad]
};

inline JointGeometry jointGeometry(const Eigen::Vector3d& prev, const Eigen::Vector3d& axis, double sigma,
                                   double sigma_prev) {
  JointGeometry g;
  g.cross = prev.cross(axis);
  g.cosine = prev.dot(axis);
  g.sine = g.cross.norm();
  g.bend = std::atan2(g.sine, g.cosine);
  g.twist = sigma - sigma_prev - transportHolonomy(prev.x(), prev.y(), prev.z(), axis.x(), axis.y(), axis.z());
  return g;
}

}  // namespace cable_dynamics
