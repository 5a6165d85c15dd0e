#pragma once
/// \file
/// \brief The water around the cable: current (uniform or a depth profile) and Morison drag.

#include <Eigen/Core>

#include "cable_dynamics/cable_params.h"

namespace cable_dynamics {

/// Current velocity as a function of depth, in the paper frame (z down) [m/s].
class CurrentField {
 public:
  explicit CurrentField(const FluidParams& fluid);

  /// Current at paper-frame depth z below the base [m]: linear in the profile, constant beyond it.
  Eigen::Vector3d at(double z) const;

  /// Replaces the field by a uniform current given in the world frame [m/s] (e.g. from a topic).
  void setUniformWorld(const Eigen::Vector3d& current_world);

 private:
  Eigen::Vector3d uniform_;                   ///< paper frame [m/s]
  Eigen::VectorXd depth_;                     ///< (rows) [m]
  Eigen::Matrix3Xd profile_;                  ///< (3 x rows) paper frame [m/s]
};

/// Morison drag per unit length on a cylinder of diameter d with axis u, moving at velocity `velocity`
/// through water moving at `current` (both [m/s]): normal part 1/2 rho C_n d |v_n| v_n on the projected
/// diameter, tangential part 1/2 rho C_t (pi d) |v_t| v_t on the wetted perimeter, v = current - velocity.
/// Returns [N/m].
Eigen::Vector3d morisonDragPerLength(const Eigen::Vector3d& axis, const Eigen::Vector3d& velocity,
                                     const Eigen::Vector3d& current, double density, double diameter,
                                     double drag_normal, double drag_tangential);

/// Gauss-Legendre nodes on [0, 1] and their weights (sum 1), for 1 to 8 points.
void gaussLegendreUnit(int points, double* nodes, double* weights);

}  // namespace cable_dynamics
