#pragma once
/// \file
/// \brief The O(n) formulation: an articulated-body recursion (Featherstone) written out for a chain of
///        axisymmetric links on spherical joints (docs/MODEL.md section 4).

#include "cable_dynamics/dynamics/chain_data.h"
#include "cable_dynamics/dynamics/chain_model.h"

namespace cable_dynamics {

/// Angular accelerations into each LinkBlock::omega_rate, data.load_force, data.added_mass_power and the
/// joint forces (all of them with `all_joint_forces`, else only joint 0's, which the input power needs),
/// after the kinematics, the external loads and the joint torques. O(n), no heap allocation. Passes:
/// linkTermsPass (each link on its own), backwardPass (serial, load to base), forwardPass (serial, base to
/// load), accelerationPass (each link on its own), jointForcesPass. With an exact anchor
/// (ChainModel::heldTip()) a first backward pass finds the anchor's force (data.coupling) that gives the
/// tip data.tip_demand. Returns false when that force is not finite.
bool solveArticulatedBody(const ChainModel& model, ChainData& data, bool all_joint_forces);

/// The change of the links' angular velocities (3 x n) [rad/s] and stretch rates (n; empty with rigid links)
/// [m/s] that an impulse on the load gives, the impulse chosen to change the tip's velocity by
/// `velocity_change` [m/s] (on the directions the chain can move its tip in): the least-kinetic-energy
/// correction of a start whose tip does not move with its anchor (a base that starts moving under a chain at
/// rest). At the loads `data` holds (ChainDynamics::computeLoads). Three passes; allocates (starts only).
bool tipVelocityProjection(const ChainModel& model, ChainData& data, const Eigen::Vector3d& velocity_change,
                           Eigen::Matrix3Xd& omega_change, Eigen::VectorXd& stretch_rate_change);

}  // namespace cable_dynamics
