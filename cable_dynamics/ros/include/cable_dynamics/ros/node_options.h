#pragma once
/// \file
/// \brief The node's parameters: the cable config (same keys as the YAML files) and the `ros` section,
///        read from the private namespace and validated by the same ConfigSection checks.

#include <string>

#include <Eigen/Core>
#include <ros/node_handle.h>
#include <yaml-cpp/yaml.h>

#include "cable_dynamics/params/cable_params.h"
#include "cable_dynamics/ros/scene_markers.h"

namespace cable_dynamics {

/// ROS-side options (private parameters under `~ros/`); ranges in docs/NODE.md, "Parameters".
struct NodeOptions {
  double rate = 100.0;                ///< simulation and publishing cycles per second [Hz]
  std::string world_frame = "world";  ///< REP-103 frame (z up) the cable lives in
  std::string frame_prefix;           ///< prepended to every frame and joint name; default "<namespace>/"
  Eigen::Vector3d base_position = Eigen::Vector3d::Zero();  ///< cable base at rest, world frame [m]
  double input_timeout = 1.0;     ///< inputs older than this, or stamped further ahead, are stale [s]
  int max_steps_per_cycle = 2000;  ///< catch-up bound per cycle, in steps (stepsPerCycleCap())
  bool max_steps_given = false;     ///< ros.max_steps_per_cycle was given: honoured as it is
  double max_lag = 1.0;            ///< simulated time behind the clock beyond this is dropped (and reported) [s]
  double tension_scale = 0.0;      ///< colour scale top [N]; 0 = the largest tension seen so far
  /// What colours the cable in rviz (`ros.markers.colour_by`: tension | utilisation).
  MarkerColour colour_by = MarkerColour::kTension;
  double diagnostics_period = 1.0;  ///< [s]
  BodyShapes shapes;                ///< rviz sizes of the vessel and the ROV (`vessel_size`, `rov_size`) [m]
  /// The lightest ROV an attached load's pose exchange must hold [kg]: the coupling is softened for it at the
  /// exchange's delay (CouplingSizer); 0 keeps the configured coupling whatever the exchange.
  double min_rov_mass = 5.0;
};

/// The most steps of `dt` [s] a cycle takes: ros.max_steps_per_cycle when given; otherwise enough for two
/// cycle periods at `options.rate` (so that a slow rate keeps real time and a late cycle can catch up), and
/// never fewer than the default 2000 (issue 27: rate 0.1 with dt 1 ms stepped 2 s of every 10 s).
int stepsPerCycleCap(const NodeOptions& options, double dt);

/// Validates the `ros` section of a parameter tree (absent: all defaults). `default_prefix` is the
/// prefix used when `frame_prefix` is not given. Throws ConfigError naming the key, the value and the
/// allowed range.
NodeOptions parseNodeOptions(const YAML::Node& ros_section, const std::string& default_prefix);

/// Reads and validates the private namespace of `private_nh`: the `ros` section into `options`, the rest
/// with the config loader into `params`. Throws ConfigError naming the key, the value and the allowed range.
/// `~tuning/` belongs to the live-tuning server (dynamic_reconfigure stores its values there) and is not
/// read. When given, `config_tree` and `ros_tree` get the two parts as read (live tuning re-checks them).
void loadNodeParameters(const ros::NodeHandle& private_nh, CableParams& params, NodeOptions& options,
                        YAML::Node* config_tree = nullptr, YAML::Node* ros_tree = nullptr);

}  // namespace cable_dynamics
