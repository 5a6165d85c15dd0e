#pragma once
/// \file
/// \brief The ROV body's built-in station keeper (load.body.station_keeping): a PD law on the pose error,
///        what an ROV's autopilot in position-hold mode does, evaluated once per step (a zero-order hold,
///        as a controller running at the simulation's rate).

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "cable_dynamics/params/cable_params.h"

namespace cable_dynamics {

/// The body's pose and twist the keeper reads: world axes (z up), origin O.
struct BodyPose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();           ///< O [m]
  Eigen::Quaterniond attitude = Eigen::Quaterniond::Identity();  ///< world from body
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();           ///< of O, world axes [m/s]
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();   ///< body frame [rad/s]
};

/// The keeper's wrench at O in the body frame [N, N m]:
///   F = R^T sat(Kp e + Ki integral(e) - Kd v + (W - B) z_world, max_force),  e = p_t - p,
///   M = sat(Ka log(R^T R_t) - Kr w, max_torque),
/// the submerged weight W - B fed forward (a trimmed ROV's thrusters hold it), each gain per axis (world
/// x, y, z for the force; body roll, pitch, yaw for the moment). `integral` [m s] is the keeper's state:
/// it gains e dt, and stops growing on an axis whose integral force alone reaches max_force (anti-windup).
/// Zero when every gain is zero.
Eigen::Matrix<double, 6, 1> stationKeepingWrench(const RovBodyParams& keeper, double submerged_weight,
                                                 const BodyPose& body, const Eigen::Vector3d& target_position,
                                                 const Eigen::Quaterniond& target_attitude, double dt,
                                                 Eigen::Vector3d& integral);

/// true when some gain of the keeper is non-zero.
bool stationKeepingEnabled(const RovBodyParams& keeper);

}  // namespace cable_dynamics
