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

/// A joint's twist [rad] brought to (-2 pi, 2 pi] (`value`: the twist's value, for an automatic-differentiation
/// scalar S; the shift is a constant, so the derivatives stay). The transport holonomy is a solid angle,
/// defined modulo 4 pi: where the arc between two steeply rising links passes over the upward pole (bent
/// across the vertical plane), its arctangent changes branch between two evaluations while the frames move
/// by nothing, and the twist spring saw two whole turns appear (config/tms_tether.yaml in a current along
/// x: 526 J in one substep, the run stopped at 0.097 s). No twist a joint can physically hold (a whole turn
/// across one joint) is changed.
template <typename S>
S principalTwist(const S& twist, double value) {
  if (std::abs(value) <= 2.0 * M_PI) return twist;
  return twist - (value - std::remainder(value, 4.0 * M_PI));
}

/// One joint of the bending model between the axes `prev` and `axis` with vertical twists sigma_prev and
/// sigma [rad].
struct JointGeometry {
  Eigen::Vector3d cross;  ///< prev x axis
  double cosine, sine;    ///< of the bend angle
  double bend, twist;     ///< [rad]
};

/// atan2(y, x) for x > 0 and |y| < 0.01 x by its series (exact to round-off: the first term left out is
/// t^11/11 < 1e-23), else the library's. The joints of a cable bend and turn little from link to link: both
/// of jointGeometry's arctangents, twice per joint and evaluation, take the series (11 % of an implicit
/// step's time with the library's).
inline double smallAtan2(double y, double x) {
  if (x > 0.0 && std::abs(y) < 0.01 * x) {
    const double t = y / x, t2 = t * t;
    return t * (1.0 - t2 * (1.0 / 3.0 - t2 * (1.0 / 5.0 - t2 * (1.0 / 7.0 - t2 / 9.0))));
  }
  return std::atan2(y, x);
}

inline JointGeometry jointGeometry(const Eigen::Vector3d& prev, const Eigen::Vector3d& axis, double sigma,
                                   double sigma_prev) {
  JointGeometry g;
  g.cross = prev.cross(axis);
  g.cosine = prev.dot(axis);
  g.sine = g.cross.norm();
  g.bend = smallAtan2(g.sine, g.cosine);
  // transportHolonomy(), with the series where the triangle is thin.
  const double vertical_triple = prev.x() * axis.y() - prev.y() * axis.x();
  const double holonomy = -2.0 * smallAtan2(vertical_triple, 1.0 + prev.z() + axis.z() + g.cosine);
  const double twist = sigma - sigma_prev - holonomy;
  g.twist = principalTwist(twist, twist);
  return g;
}

}  // namespace cable_dynamics
