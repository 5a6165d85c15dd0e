#pragma once
/// \file
/// \brief The first pass of every evaluation: link axes, angular velocities and the base end of each
///        link, its velocity and its acceleration at zero angular accelerations.

#include <Eigen/Core>

#include "cable_dynamics/dynamics/chain_data.h"
#include "cable_dynamics/dynamics/chain_model.h"
#include "cable_dynamics/dynamics/state_layout.h"

namespace cable_dynamics {

/// Fills data.links (u, omega, axis_rate, beta, base_pos, base_vel, known_acc, twist_rate) and the tip
/// from the state x (size StateLayout::size(n)) and the base's motion in `ends`. O(n).
void computeKinematics(const ChainModel& model, ChainData& data, const Eigen::VectorXd& x, const EndInputs& ends);

}  // namespace cable_dynamics
