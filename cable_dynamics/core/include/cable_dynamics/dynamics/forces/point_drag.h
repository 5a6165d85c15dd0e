#pragma once
/// \file
/// \brief Isotropic quadratic drag of a point, the load or an attachment of C_d A = `drag_area` [m^2]:
///        F = 1/2 rho C_d A |r| r with r = current - velocity [N]. Its value, power, Jacobian and form at
///        rest, side by side: external_loads.cpp (explicit), stiff_articulated_body.cpp (the load's
///        linearization) and static_equations.cpp (the statics) call them. The links' own Morison drag,
///        integrated along each link in SIMD lanes, is LinkDrag (fluid.h).

#include <Eigen/Core>

namespace cable_dynamics {

/// The drag on a point moving at `velocity` through water moving at `current` [m/s]: density [kg/m^3].
inline Eigen::Vector3d pointDrag(double density, double drag_area, const Eigen::Vector3d& velocity,
                                 const Eigen::Vector3d& current) {
  const Eigen::Vector3d relative = current - velocity;
  return (0.5 * density * drag_area * relative.norm()) * relative;
}

/// Its power on the point [W] (negative in still water: it takes energy out).
inline double pointDragPower(const Eigen::Vector3d& drag, const Eigen::Vector3d& velocity) { return drag.dot(velocity); }

/// Its damping -dF/dv = 1/2 rho C_d A (|r| I + r r^T / |r|) [N s/m] (the implicit step's).
inline Eigen::Matrix3d pointDragDamping(double density, double drag_area, const Eigen::Vector3d& velocity,
                                        const Eigen::Vector3d& current) {
  const Eigen::Vector3d relative = current - velocity;
  const double speed = relative.norm(), k = 0.5 * density * drag_area;
  Eigen::Matrix3d damping = (k * speed) * Eigen::Matrix3d::Identity();
  if (speed > 1e-12) damping += (k / speed) * relative * relative.transpose();
  return damping;
}

/// At rest (velocity zero), for the statics: the current's drag alone [N].
inline Eigen::Vector3d pointDragAtRest(double density, double drag_area, const Eigen::Vector3d& current) {
  return pointDrag(density, drag_area, Eigen::Vector3d::Zero(), current);
}

}  // namespace cable_dynamics
