#pragma once
/// \file
/// \brief The generated model at one state as JSON (the output of the `cable_model` tool).

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "cable_dynamics/params/cable_params.h"

namespace cable_dynamics {

/// Every derived parameter, the state, and M, h, G, K, elastic, D at (q [rad], qd [rad/s]).
nlohmann::json modelReport(const CableParams& params, const Eigen::VectorXd& q, const Eigen::VectorXd& qd);

}  // namespace cable_dynamics
