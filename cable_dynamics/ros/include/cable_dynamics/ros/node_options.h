#pragma once
/// \file
/// \brief The node's parameters: the cable config (same keys as the YAML files) and the `ros` section,
///        read from the private namespace and validated.

#include <string>

#include <Eigen/Core>
#include <ros/node_handle.h>

#include "cable_dynamics/params/cable_params.h"

namespace cable_dynamics {

/// ROS-side options (private parameters under `~ros/`).
struct NodeOptions {
  double rate = 100.0;                  ///< simulation and publishing cycles per second [Hz]
  std::string world_frame = "world";    ///< REP-103 frame (z up) the cable lives in
  std::string frame_prefix;             ///< prepended to every frame and joint name; default "<namespace>/"
  Eigen::Vector3d base_position = Eigen::Vector3d::Zero();  ///< cable base at rest, world frame [m]
  double input_timeout = 1.0;           ///< inputs older than this are stale [s]
  int max_steps_per_cycle = 2000;       ///< catch-up bound per cycle; beyond it the lag is reported
  double tension_scale = 0.0;           ///< colour scale top [N]; 0 = the largest tension seen so far
  double diagnostics_period = 1.0;      ///< [s]
};

/// Reads and validates the private namespace of `private_nh`. Throws ConfigError naming the key, the
/// value and the allowed range.
void loadNodeParameters(const ros::NodeHandle& private_nh, CableParams& params, NodeOptions& options);

}  // namespace cable_dynamics
