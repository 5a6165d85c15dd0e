#pragma once
/// \file
/// \brief The bending model's joint blocks (docs/MODEL.md section 5): the Jacobian of a joint's spring
///        and damper across and about its mean axis, and the bend spring's torque, shared by the joints
///        between links, the base's clamp and the tip's clamp (forces/tip_clamp.h). The joints' torques
///        on the links are computed in joint_torques.cpp (the explicit pass) with the geometry of
///        joint_geometry.h; the implicit step's blocks (stiff_articulated_body.cpp) and the statics'
///        bend torque (static_equations.cpp) come from here.

#include <cmath>

#include <Eigen/Core>

#include "cable_dynamics/dynamics/joint_geometry.h"

namespace cable_dynamics {

/// The unit bisector of two axes, or `fallback` where they are opposite (the joint blocks' mean axis).
inline Eigen::Vector3d meanAxis(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& fallback) {
  const Eigen::Vector3d sum = a + b;
  return sum.norm() > 1e-9 ? Eigen::Vector3d(sum.normalized()) : fallback;
}

/// A joint's spring (or damper) block on the relative rotation of its two bodies, with mean axis m:
/// `across` for bending, `about` for twist, K = across (I - m m^T) + about m m^T. The tangent of the
/// bend spring's torque at zero bend (and of the damper's at any), the implicit step's approximation
/// elsewhere (a W-method: it costs no order).
inline Eigen::Matrix3d jointBlock(double across, double about, const Eigen::Vector3d& m) {
  const Eigen::Matrix3d mm = m * m.transpose();
  return across * (Eigen::Matrix3d::Identity() - mm) + about * mm;
}

/// The bend spring V = 1/2 k beta^2 between the axes `prev` and `axis` (beta the angle between them, sine
/// its sine, cross = prev x axis): its torque on the body of `axis`, -k beta/sin(beta) (prev x axis) [N m]
/// (the body of `prev` gets the opposite). dV = k beta/sin(beta) (prev x axis) . dTheta.
inline Eigen::Vector3d bendSpringTorque(double k, double bend, double sine, const Eigen::Vector3d& cross) {
  return -k * bendOverSine(bend, sine) * cross;
}

/// The same from the two axes.
inline Eigen::Vector3d bendSpringTorque(double k, const Eigen::Vector3d& prev, const Eigen::Vector3d& axis) {
  const Eigen::Vector3d cross = prev.cross(axis);
  const double sine = cross.norm(), bend = std::atan2(sine, prev.dot(axis));
  return bendSpringTorque(k, bend, sine, cross);
}

}  // namespace cable_dynamics
