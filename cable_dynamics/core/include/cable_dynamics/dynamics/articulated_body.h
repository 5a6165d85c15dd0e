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

}  // namespace cable_dynamics
