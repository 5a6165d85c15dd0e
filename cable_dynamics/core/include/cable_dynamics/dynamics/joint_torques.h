#pragma once
/// \file
/// \brief The fictitious joints' springs and dampers as torques on the links (world/paper axes), and
///        their elastic energy: the paper's diagonal K and D on the generalized coordinates, or the
///        bending model's bend and twist between neighbours (docs/MODEL.md section 5).

#include <Eigen/Core>

#include "cable_dynamics/dynamics/chain_data.h"
#include "cable_dynamics/dynamics/chain_model.h"

namespace cable_dynamics {

/// Fills data.spring_torque, data.damping_torque (zero when `with_dampers` is false) and each link's
/// torque (their sum), after computeKinematics(). Does nothing for the paper model without springs
/// (every torque stays zero from construction). O(n).
void computeJointTorques(const ChainModel& model, ChainData& data, const Eigen::VectorXd& x, bool with_dampers = true);

/// Energy of the joint springs at x [J], after computeKinematics() (the paper model reads its
/// coordinates into data's scratch). O(n).
double elasticEnergy(const ChainModel& model, ChainData& data, const Eigen::VectorXd& x);

/// The joint springs' generalized forces on the paper coordinates, dV/dq (3n) [N m], at the torques
/// computeJointTorques() left in `data` for state x (so with the clamps as the ends had them): what the
/// node publishes as the joints' efforts (their negative). Not the hot path (the snapshot's).
void springGeneralizedForces(const ChainModel& model, ChainData& data, const Eigen::VectorXd& x, Eigen::VectorXd& out);

/// Power of the joint dampers [W] (negative: they take energy out), after computeJointTorques().
double damperPower(const ChainModel& model, const ChainData& data);

/// Power of the winch's held joints' moments (ChainDeployment::jointHold) on the links [W], after
/// computeKinematics() and ChainDynamics::applyEnds(); booked with the losses (lossPower).
double jointHoldPower(const ChainData& data);

}  // namespace cable_dynamics
