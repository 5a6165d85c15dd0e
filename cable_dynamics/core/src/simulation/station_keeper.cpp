#include "cable_dynamics/simulation/station_keeper.h"

namespace cable_dynamics {
namespace {

/// v scaled down to at most `limit` in norm.
Eigen::Vector3d saturated(const Eigen::Vector3d& v, double limit) {
  const double norm = v.norm();
  return norm > limit ? Eigen::Vector3d(v * (limit / norm)) : v;
}

}  // namespace

bool stationKeepingEnabled(const RovBodyParams& k) {
  return !(k.position_gain.isZero() && k.velocity_gain.isZero() && k.attitude_gain.isZero() && k.rate_gain.isZero());
}

Eigen::Matrix<double, 6, 1> stationKeepingWrench(const RovBodyParams& k, double submerged_weight, const BodyPose& body,
                                                 const Eigen::Vector3d& target_position,
                                                 const Eigen::Quaterniond& target_attitude) {
  Eigen::Matrix<double, 6, 1> wrench = Eigen::Matrix<double, 6, 1>::Zero();
  if (!stationKeepingEnabled(k)) return wrench;
  Eigen::Vector3d force = k.position_gain.cwiseProduct(target_position - body.position) -
                          k.velocity_gain.cwiseProduct(body.velocity);
  force.z() += submerged_weight;  // world z up: holds the weight less the buoyancy
  // The attitude error as a rotation vector in the body frame, the shorter way round.
  Eigen::Quaterniond error = body.attitude.conjugate() * target_attitude;
  if (error.w() < 0.0) error.coeffs() *= -1.0;
  const Eigen::AngleAxisd turn(error);
  const Eigen::Vector3d rotation = turn.angle() * turn.axis();
  const Eigen::Vector3d moment = k.attitude_gain.cwiseProduct(rotation) - k.rate_gain.cwiseProduct(body.angular_velocity);
  wrench << body.attitude.conjugate() * saturated(force, k.max_force), saturated(moment, k.max_torque);
  return wrench;
}

}  // namespace cable_dynamics
