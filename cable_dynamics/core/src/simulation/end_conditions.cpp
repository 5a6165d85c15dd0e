#include "cable_dynamics/simulation/end_conditions.h"

#include <cmath>

#include "cable_dynamics/dynamics/frames.h"
#include "cable_dynamics/simulation/body_motion.h"

namespace cable_dynamics {

void motionAt(const MotionParams& m, const Eigen::Vector3d& offset, double t, Eigen::Vector3d& p, Eigen::Vector3d& v,
              Eigen::Vector3d& a) {
  bodyPointAt(m, offset, t, p, v, a);
  p = worldToPaper(p);
  v = worldToPaper(v);
  a = worldToPaper(a);
}

EndConditions::EndConditions(const BaseParams& base, const LoadParams& load, const WinchParams& winch)
    : base_(base), load_(load), has_winch_(winch.enabled), winch_(winch) {}

void EndConditions::reset() {
  external_load_ = false;
  external_base_ = false;
}

EndInputs EndConditions::at(double t) const {
  EndInputs ends;
  if (external_base_) {
    ends.base_position = base_position_;
    ends.base_velocity = base_velocity_;
  } else {
    motionAt(base_.motion, base_.hang_off, t, ends.base_position, ends.base_velocity, ends.base_acceleration);
  }
  ends.load_coupled = load_.mode != LoadMode::kFree;
  if (external_load_) {
    ends.target_position = load_position_;
    ends.target_velocity = load_velocity_;
  } else if (ends.load_coupled) {
    Eigen::Vector3d acceleration;
    motionAt(load_.motion, load_.attachment, t, ends.target_position, ends.target_velocity, acceleration);
    ends.target_position += initial_tip_;
    if (load_.mode == LoadMode::kAnchored) ends.target_velocity.setZero();
  }
  if (has_winch_) {
    const WinchMotion m = winch_.at(t);
    ends.winch = true;
    ends.winch_length = m.length - outboard_length_;
    ends.winch_speed = m.speed;
    ends.winch_acceleration = m.acceleration;
  }
  return ends;
}

void EndConditions::setLoadTarget(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity,
                                  const Eigen::Quaterniond& attitude) {
  external_load_ = true;
  load_position_ = worldToPaper(position);
  load_velocity_ = worldToPaper(velocity);
  load_attitude_ = attitude.normalized();
}

void EndConditions::setBaseTarget(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity,
                                  const Eigen::Quaterniond& attitude) {
  external_base_ = true;
  base_position_ = worldToPaper(position);
  base_velocity_ = worldToPaper(velocity);
  base_attitude_ = attitude.normalized();
}

namespace {
Eigen::Quaterniond configuredAttitude(const MotionParams& motion, double t) {
  if (motion.attitude_amplitude.isZero()) return Eigen::Quaterniond::Identity();
  Eigen::Matrix3d rotation, rate, acceleration;
  attitudeAt(motion, t, rotation, rate, acceleration);
  return Eigen::Quaterniond(rotation);
}
}  // namespace

Eigen::Quaterniond EndConditions::baseAttitude(double t) const {
  return external_base_ ? base_attitude_ : configuredAttitude(base_.motion, t);
}

Eigen::Quaterniond EndConditions::loadAttitude(double t) const {
  return external_load_ ? load_attitude_ : configuredAttitude(load_.motion, t);
}

}  // namespace cable_dynamics
