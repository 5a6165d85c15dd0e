#pragma once
/// \file
/// \brief The node's side of an ROV body simulated here (load.mode body): its odometry out, its thrust and
///        station-keeping target in. Only fills and checks messages; the node subscribes and publishes.

#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/WrenchStamped.h>
#include <nav_msgs/Odometry.h>

#include "cable_dynamics/simulation/cable_simulator.h"

namespace cable_dynamics {

/// rov_odom: the ROV's origin and attitude in `world_frame` (the base's rest position added back), its
/// twist in its own frame `rov_frame` (REP-105's child frame), from the snapshot.
void fillRovOdometry(const SimulationSnapshot& s, const Eigen::Vector3d& base_position, const ros::Time& stamp,
                     const std::string& world_frame, const std::string& rov_frame, nav_msgs::Odometry& out);

/// rov_thrust (body frame, at the ROV's origin) as force and torque; false with `why` when a component is
/// not finite or beyond +-kMaxThrust, or the frame is neither empty nor `rov_frame`.
bool readThrust(const geometry_msgs::WrenchStamped& msg, const std::string& rov_frame, Eigen::Vector3d& force,
                Eigen::Vector3d& torque, std::string& why);

/// rov_target (the station keeper's target, `world_frame` or empty) as position from the base's rest
/// position and attitude; false with `why` when not finite, not a unit quaternion, or another frame.
bool readBodyTarget(const geometry_msgs::PoseStamped& msg, const std::string& world_frame,
                    const Eigen::Vector3d& base_position, Eigen::Vector3d& position, Eigen::Quaterniond& attitude,
                    std::string& why);

}  // namespace cable_dynamics
