#pragma once
/// \file
/// \brief The dense formulation: the 3n x 3n mass matrix of the angular velocities, assembled in O(n^2)
///        and solved by Cholesky in O(n^3) (docs/MODEL.md section 6). The reference the recursion is
///        held against, and the mass matrix the semi-implicit integrator needs.

#include "cable_dynamics/dynamics/chain_data.h"
#include "cable_dynamics/dynamics/chain_model.h"

namespace cable_dynamics {

/// The generalized forces (right-hand side of M omega' = rhs) into data.dense.rhs, with the inertia
/// tensors and outboard sums the mass matrix needs, after the kinematics, the external loads and the
/// joint torques. O(n). data.dense must be allocated.
void assembleGeneralizedForces(const ChainModel& model, ChainData& data);

/// The mass matrix into data.dense.mass_matrix, after assembleGeneralizedForces(). O(n^2).
void assembleMassMatrix(const ChainModel& model, ChainData& data);

/// Solves for the angular accelerations (into each LinkBlock::omega_rate and data.dense.omega_rate), the
/// joint forces, the load force and the added-mass power, after the kinematics, loads and torques.
/// Returns false when the mass matrix is not positive definite.
bool solveDense(const ChainModel& model, ChainData& data);

/// Joint forces, the load force and the added-mass power from angular accelerations `omega_rate` (3n)
/// [rad/s^2] (used by solveDense and by the semi-implicit step with its mean acceleration).
void denseJointForces(const ChainModel& model, ChainData& data, const Eigen::VectorXd& omega_rate);

}  // namespace cable_dynamics
