#pragma once
/// \file
/// \brief States in the paper's coordinates: the configured initial one and reproducible random ones.

#include <Eigen/Core>

#include "cable_dynamics/params/cable_params.h"

namespace cable_dynamics {

/// A reproducible state away from the zero-elevation singularity: te in [0.2, 1.3] rad, a and t in
/// [-pi, pi] rad, rates in [-1, 1] rad/s.
void randomState(int links, unsigned seed, Eigen::VectorXd& q, Eigen::VectorXd& qd);

/// The configured initial state (q from `initial`, qd = 0).
void initialState(const CableParams& params, Eigen::VectorXd& q, Eigen::VectorXd& qd);

}  // namespace cable_dynamics
