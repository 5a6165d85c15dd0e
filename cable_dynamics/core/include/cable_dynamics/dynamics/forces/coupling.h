#pragma once
/// \file
/// \brief The load's PD coupling to its anchor or to the ROV's attachment point (docs/MODEL.md, the load):
///        its value, its power, its Jacobian and its form at rest, side by side. The explicit evaluation
///        (external_loads.cpp), the implicit step's linearization (stiff_articulated_body.cpp) and its
///        power at the step's end (linear_implicit.cpp), and the statics (static_equations.cpp) call it.
///        Paper frame (z down).

#include <Eigen/Core>

namespace cable_dynamics {

/// F = -k (x - x_t) - c (v - v_t) on the load at the tip x moving at v, from the target x_t moving at v_t.
/// Isotropic: its Jacobians are scalars times the identity.
struct LoadCoupling {
  double stiffness = 0.0;  ///< k [N/m]
  double damping = 0.0;    ///< c [N s/m]

  /// The force on the load [N]: tip, target [m]; their velocities [m/s].
  Eigen::Vector3d force(const Eigen::Vector3d& tip, const Eigen::Vector3d& tip_velocity, const Eigen::Vector3d& target,
                        const Eigen::Vector3d& target_velocity) const {
    return -stiffness * (tip - target) - damping * (tip_velocity - target_velocity);
  }

  /// Its power on the cable [W]: F . v with v the tip's velocity (a work input: the target is driven).
  static double power(const Eigen::Vector3d& force, const Eigen::Vector3d& tip_velocity) { return force.dot(tip_velocity); }

  /// Its Jacobian: -dF/dx = k I and -dF/dv = c I, as the two scalars (the implicit step adds
  /// c_D c + c_K k to the load's mass).
  double stiffnessJacobian() const { return stiffness; }
  double dampingJacobian() const { return damping; }

  /// The change of the power F . v when the tip moves from (x, v) by (dx, dv), to first order [W], F being
  /// linear in both: (F + dF) . (v + dv) - F.v = F.dv - (k dx + c dv).v + O(d^2).
  double powerShift(const Eigen::Vector3d& force, const Eigen::Vector3d& tip_velocity, const Eigen::Vector3d& dx,
                    const Eigen::Vector3d& dv) const {
    return force.dot(dv) - (stiffness * dx + damping * dv).dot(tip_velocity);
  }

  /// At rest (both velocities zero: the damper does nothing), for the statics [N].
  Eigen::Vector3d atRest(const Eigen::Vector3d& tip, const Eigen::Vector3d& target) const {
    return -stiffness * (tip - target);
  }
};

}  // namespace cable_dynamics
