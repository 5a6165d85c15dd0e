#pragma once
/// \file
/// \brief A clamped tip (load.fixity: clamped; docs/MODEL.md section 5): a bend spring k and damper c
///        between the last link's axis u and the clamp's axis a, no twist spring (a swivel). Its value,
///        energy, power, Jacobian and form at rest, side by side: joint_torques.cpp (the explicit pass and
///        the elastic energy), stiff_articulated_body.cpp (the implicit step's blocks) and
///        static_equations.cpp (the statics) call it. Written as a joint whose inboard body is the last
///        link and whose outboard body is the clamp: the torques below are on the clamp, the last link
///        gets their opposite. Its power is the clamp's torque at the clamp's angular velocity (the ends'
///        input, forces/power_balance.h).

#include <cmath>

#include <Eigen/Core>

#include "cable_dynamics/dynamics/forces/joint_springs.h"

namespace cable_dynamics {

struct TipClamp {
  double stiffness = 0.0;  ///< k [N m/rad]
  double damping = 0.0;    ///< c [N m s/rad]

  bool active() const { return stiffness > 0.0 || damping > 0.0; }

  /// The bend angle between u and a [rad].
  static double bend(const Eigen::Vector3d& u, const Eigen::Vector3d& a) { return std::atan2(u.cross(a).norm(), u.dot(a)); }

  /// The spring's torque on the clamp, -k beta/sin(beta) (u x a) [N m] (its form at rest too: the statics').
  Eigen::Vector3d springOnClamp(const Eigen::Vector3d& u, const Eigen::Vector3d& a) const {
    return bendSpringTorque(stiffness, u, a);
  }

  /// The damper's torque on the clamp [N m]: -c times the relative angular velocity (clamp's less the
  /// link's) across the mean axis of u and a.
  Eigen::Vector3d damperOnClamp(const Eigen::Vector3d& u, const Eigen::Vector3d& a, const Eigen::Vector3d& link_omega,
                                const Eigen::Vector3d& clamp_omega) const {
    const Eigen::Vector3d relative = clamp_omega - link_omega;
    const Eigen::Vector3d direction = (u + a).normalized();
    return -damping * (relative - relative.dot(direction) * direction);
  }

  /// The spring's energy 1/2 k beta^2 [J].
  double energy(const Eigen::Vector3d& u, const Eigen::Vector3d& a) const {
    const double beta = bend(u, a);
    return 0.5 * stiffness * beta * beta;
  }

  /// Its blocks on the last link's rotation relative to the clamp: stiffness k (I - m m^T) [N m/rad] and
  /// damping c (I - m m^T) [N m s/rad], m the mean of u and a (jointBlock, no twist).
  void jacobian(const Eigen::Vector3d& u, const Eigen::Vector3d& a, Eigen::Matrix3d& spring, Eigen::Matrix3d& damper) const {
    const Eigen::Vector3d mean = meanAxis(u, a, a);
    spring = jointBlock(stiffness, 0.0, mean);
    damper = jointBlock(damping, 0.0, mean);
  }
};

}  // namespace cable_dynamics
