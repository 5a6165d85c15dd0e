#pragma once
/// \file
/// \brief Kinetic and potential energy of the chain and its load from the kinematics.

#include "cable_dynamics/dynamics/chain_data.h"
#include "cable_dynamics/dynamics/chain_model.h"

namespace cable_dynamics {

/// Kinetic energy [J] (cable and load, without the fluid's added mass) and potential energy of gravity
/// minus buoyancy, zero at the base's rest height [J], after computeKinematics(). O(n).
void kineticAndPotentialEnergy(const ChainModel& model, const ChainData& data, double& kinetic, double& potential);

}  // namespace cable_dynamics
