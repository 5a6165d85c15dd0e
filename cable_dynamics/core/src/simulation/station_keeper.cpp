#include "cable_dynamics/simulation/station_keeper.h"

#include <cmath>

namespace cable_dynamics {
namespace {

/// v scaled down to at most `limit` in norm.
Eigen::Vector3d saturated(const Eigen::Vector3d& v, double limit) {
  const double norm = v.norm();
  return norm > limit ? Eigen::Vector3d(v * (limit / norm)) : v;
}

}  // namespace

bool stationKeepingEnabled(const RovBodyParams& k) {
  return !(k.position_gain.isZero() && k.velocity_gain.isZero() && k.integral_gain.isZero() &&
           k.attitude_gain.isZero() && k.rate_gain.isZero());
}

Eigen::Matrix<double, 6, 1> stationKeepingWrench(const RovBodyParams& k, double submerged_weight, const BodyPose& body,
                                                 const Eigen::Vector3d& target_position,
                                                 const Eigen::Quaterniond& target_attitude, double dt,
                                                 Eigen::Vector3d& integral) {
  Eigen::Matrix<double, 6, 1> wrench = Eigen::Matrix<double, 6, 1>::Zero();
  if (!stationKeepingEnabled(k)) return wrench;
  const Eigen::Vector3d error = target_position - body.position;
  for (int axis = 0; axis < 3; ++axis) {  // anti-windup: no growth beyond what the thrusters can give
    const double next = integral(axis) + error(axis) * dt;
    if (std::abs(k.integral_gain(axis) * next) <= k.max_force || std::abs(next) < std::abs(integral(axis))) {
      integral(axis) = next;
    }
  }
  Eigen::Vector3d force = k.position_gain.cwiseProduct(error) + k.integral_gain.cwiseProduct(integral) -
                          k.velocity_gain.cwiseProduct(body.velocity);
  force.z() += submerged_weight;  // world z up: holds the weight less the buoyancy
  // The attitude error as a rotation vector in the body frame, the shorter way round.
  Eigen::Quaterniond turn_error = body.attitude.conjugate() * target_attitude;
  if (turn_error.w() < 0.0) turn_error.coeffs() *= -1.0;
  const Eigen::AngleAxisd turn(turn_error);
  const Eigen::Vector3d rotation = turn.angle() * turn.axis();
  const Eigen::Vector3d moment = k.attitude_gain.cwiseProduct(rotation) - k.rate_gain.cwiseProduct(body.angular_velocity);
  wrench << body.attitude.conjugate() * saturated(force, k.max_force), saturated(moment, k.max_torque);
  return wrench;
}

}  // namespace cable_dynamics
