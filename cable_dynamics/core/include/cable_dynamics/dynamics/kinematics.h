#pragma once
/// \file
/// \brief The first pass of every evaluation: link axes, angular velocities and the base end of each
///        link, its velocity and its acceleration at zero angular accelerations.

#include <Eigen/Core>

#include "cable_dynamics/dynamics/chain_data.h"
#include "cable_dynamics/dynamics/chain_model.h"
#include "cable_dynamics/dynamics/link_block.h"
#include "cable_dynamics/dynamics/state_layout.h"

namespace cable_dynamics {

/// A link's far end's acceleration at zero angular and stretch accelerations [m/s^2]: from its base end's
/// `known` one, (l + s) beta + 2 s' u' more, with lever = l + s [m], rate = s' [m/s] (s = 0 for rigid links).
inline Vec3 farEndKnownAcceleration(const Vec3& known, const Vec3& beta, const Vec3& axis_rate, double lever, double rate) {
  return known + lever * beta + (2.0 * rate) * axis_rate;
}

/// Fills data.links (u, omega, axis_rate, beta, base_pos, base_vel, known_acc, twist_rate) and the tip
/// from the state x (size StateLayout::size(n)) and the base's motion in `ends`. O(n).
void computeKinematics(const ChainModel& model, ChainData& data, const Eigen::VectorXd& x, const EndInputs& ends);

}  // namespace cable_dynamics
