#include "cable_dynamics/simulation/end_conditions.h"

#include <cmath>

#include "cable_dynamics/dynamics/frames.h"

namespace cable_dynamics {

void motionAt(const MotionParams& m, double t, Eigen::Vector3d& p, Eigen::Vector3d& v, Eigen::Vector3d& a) {
  const double w = 2.0 * M_PI / m.period, angle = w * t + m.phase;
  p = worldToPaper(m.offset + m.amplitude * std::sin(angle) + m.velocity * t);
  v = worldToPaper(m.amplitude * (w * std::cos(angle)) + m.velocity);
  a = worldToPaper(m.amplitude * (-w * w * std::sin(angle)));
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
    motionAt(base_.motion, t, ends.base_position, ends.base_velocity, ends.base_acceleration);
  }
  ends.load_coupled = load_.mode != LoadMode::kFree;
  if (external_load_) {
    ends.target_position = load_position_;
    ends.target_velocity = load_velocity_;
  } else if (ends.load_coupled) {
    Eigen::Vector3d acceleration;
    motionAt(load_.motion, t, ends.target_position, ends.target_velocity, acceleration);
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

void EndConditions::setLoadTarget(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity) {
  external_load_ = true;
  load_position_ = worldToPaper(position);
  load_velocity_ = worldToPaper(velocity);
}

void EndConditions::setBaseTarget(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity) {
  external_base_ = true;
  base_position_ = worldToPaper(position);
  base_velocity_ = worldToPaper(velocity);
}

}  // namespace cable_dynamics
