#pragma once
/// \file
/// \brief A prescribed rigid-body motion (a vessel's, an ROV's): translation and attitude over time,
///        and the motion of a point fixed on the body (the hang-off point, the tether's attachment),
///        with exact first and second derivatives. World frame (REP-103, z up).

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "cable_dynamics/params/cable_params.h"

namespace cable_dynamics {

/// The body's attitude at time t: R = Rz(yaw) Ry(pitch) Rx(roll), each angle
/// attitude_amplitude_i sin(2 pi t / period + attitude_phase_i) [rad], and its first and second
/// time derivatives (3 x 3 matrices, [1/s], [1/s^2]).
void attitudeAt(const MotionParams& motion, double t, Eigen::Matrix3d& rotation, Eigen::Matrix3d& rate,
                Eigen::Matrix3d& acceleration);

/// The point `offset` (body frame [m]) of a body moving by `motion`, relative to where that point is at
/// rest: the translation plus (R(t) - I) offset. Position [m], velocity [m/s] and acceleration [m/s^2]
/// in the world frame.
void bodyPointAt(const MotionParams& motion, const Eigen::Vector3d& offset, double t, Eigen::Vector3d& position,
                 Eigen::Vector3d& velocity, Eigen::Vector3d& acceleration);

/// A force [N] applied at the point `offset` (body frame [m]) of a body with attitude `attitude` (a
/// frame's rotation from the body's axes), as a wrench about the body's origin: in that frame's axes and
/// in body axes.
struct BodyWrench {
  /// In the frame the attitude maps the body's axes into (the paper frame in a SimulationSnapshot) [N], [N m].
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_body = Eigen::Vector3d::Zero(), moment_body = Eigen::Vector3d::Zero();  ///< body axes [N], [N m]
};
BodyWrench wrenchAboutOrigin(const Eigen::Vector3d& force, const Eigen::Quaterniond& attitude,
                             const Eigen::Vector3d& offset);

}  // namespace cable_dynamics
