#include "cable_dynamics/simulation/end_conditions.h"

#include <algorithm>
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

namespace {

/// P = diag(1, -1, -1): the half turn about x between the world and the paper frame.
Eigen::Matrix3d worldToPaperRotation(const Eigen::Matrix3d& world) {
  const Eigen::Matrix3d p = Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal();
  return p * world * p;
}

/// The twist sigma = psi + phi of a link frame F = Rz(-psi) Rx(-te) Rz(-phi) (paper frame; the frame whose
/// angular velocity is -psi' z - te' n - phi' u, paper_coordinates.cpp), nearest to `near` [rad]: for the
/// z-x-z angles (a, b, c) of F, F00 + F11 = cos(a + c)(1 + cos b) and F10 - F01 = sin(a + c)(1 + cos b).
double frameTwist(const Eigen::Matrix3d& f, double near) {
  const double twist = -std::atan2(f(1, 0) - f(0, 1), f(0, 0) + f(1, 1));
  return twist + 2.0 * M_PI * std::round((near - twist) / (2.0 * M_PI));
}

/// vee(R' R^T): the angular velocity of a rotation R with rate R' [rad/s].
Eigen::Vector3d angularVelocity(const Eigen::Matrix3d& rotation, const Eigen::Matrix3d& rate) {
  const Eigen::Matrix3d w = rate * rotation.transpose();
  return 0.5 * Eigen::Vector3d(w(2, 1) - w(1, 2), w(0, 2) - w(2, 0), w(1, 0) - w(0, 1));
}

}  // namespace

void EndConditions::setRestClamp(const Eigen::Vector3d& axis, double twist) {
  const double elevation = std::atan2(std::hypot(axis.x(), axis.y()), axis.z());
  rest_clamp_ = Eigen::AngleAxisd(-twist, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
                Eigen::AngleAxisd(-elevation, Eigen::Vector3d::UnitX()).toRotationMatrix();
  rest_clamp_twist_ = twist;
  external_clamp_twist_ = twist;
}

EndConditions::EndConditions(const BaseParams& base, const LoadParams& load, const WinchParams& winch)
    : base_(base), load_(load), has_winch_(winch.enabled), winch_(winch) {}

void EndConditions::reset() {
  external_load_ = false;
  external_base_ = false;
  load_attitude_ = base_attitude_ = Eigen::Quaterniond::Identity();
  external_clamp_twist_ = rest_clamp_twist_;
  body_thrust_.setZero();
  hold_offset_.setZero();
  coupling_shift_.setZero();
}

void EndConditions::couplingRestShift(double t, Eigen::Vector3d& shift, Eigen::Vector3d& rate) const {
  if (coupling_shift_.isZero() || couplingIntegral()) {  // an integral's shift holds between steps
    shift = coupling_shift_;
    rate.setZero();
    return;
  }
  const double a = std::max(t - coupling_shift_time_, 0.0) / kCouplingShiftBleed, decay = std::exp(-a);
  shift = (1.0 + a) * decay * coupling_shift_;
  rate = (-a * decay / kCouplingShiftBleed) * coupling_shift_;
}

EndInputs EndConditions::at(double t) const {
  EndInputs ends;
  ends.time = t;
  if (external_base_) {
    ends.base_position = base_position_;
    ends.base_velocity = base_velocity_;
  } else {
    motionAt(base_.motion, base_.hang_off, t, ends.base_position, ends.base_velocity, ends.base_acceleration);
  }
  ends.load_coupled = load_.mode == LoadMode::kAnchored || load_.mode == LoadMode::kAttached;
  ends.body_thrust = body_thrust_;
  if (external_load_) {
    // First-order hold: the pose carried on by its velocity, within the extrapolation limit.
    const double ahead = t - load_time_;
    const bool moving = std::abs(ahead) <= kTargetExtrapolation;
    ends.target_position = load_position_ + std::clamp(ahead, -kTargetExtrapolation, kTargetExtrapolation) * load_velocity_;
    ends.target_velocity = moving ? load_velocity_ : Eigen::Vector3d::Zero();
  } else if (ends.load_coupled) {
    motionAt(load_.motion, load_.attachment, t, ends.target_position, ends.target_velocity, ends.target_acceleration);
    ends.target_position += initial_tip_;
    // A spring anchor's damper holds the tip still; an exact anchor follows a moving anchor's motion.
    if (load_.mode == LoadMode::kAnchored && !load_.heldExactly()) ends.target_velocity.setZero();
    if (load_.mode != LoadMode::kAnchored || !load_.heldExactly()) ends.target_acceleration.setZero();
  }
  if (load_.heldExactly()) ends.target_position += hold_offset_;  // zero unless the steps hold it by a spring
  if (ends.load_coupled) couplingRestShift(t, ends.coupling_rest_shift, ends.coupling_rest_shift_rate);
  // The clamp turns with the vessel: its frame is the vessel's rotation of its rest frame.
  if (external_base_ ? base_attitude_.coeffs() != Eigen::Quaterniond::Identity().coeffs()
                     : !base_.motion.attitude_amplitude.isZero()) {
    Eigen::Matrix3d rotation = base_attitude_.toRotationMatrix(), rate = Eigen::Matrix3d::Zero(), acceleration;
    if (!external_base_) attitudeAt(base_.motion, t, rotation, rate, acceleration);
    const Eigen::Matrix3d frame = worldToPaperRotation(rotation) * rest_clamp_;
    ends.clamp_moves = true;
    ends.clamp_axis = frame.col(2);
    ends.clamp_twist = frameTwist(frame, external_base_ ? external_clamp_twist_ : rest_clamp_twist_);
    // An external attitude comes without its rate (the pose stream's rotation is not differentiated):
    // the clamp's damper then acts on the base link's own angular velocity.
    ends.clamp_omega = external_base_ ? Eigen::Vector3d::Zero() : worldToPaper(angularVelocity(rotation, rate));
  }
  // An attached ROV's clamp turns with the ROV (its direction is in the ROV's frame).
  if (load_.mode == LoadMode::kAttached && load_.fixity == TipFixity::kClamped) {
    Eigen::Matrix3d rotation = load_attitude_.toRotationMatrix(), rate = Eigen::Matrix3d::Zero(), acceleration;
    if (!external_load_ && !load_.motion.attitude_amplitude.isZero()) attitudeAt(load_.motion, t, rotation, rate, acceleration);
    ends.tip_clamp_moves = true;
    ends.tip_clamp_axis = worldToPaper(rotation * load_.direction);
    // As the base's: an external attitude comes without its rate.
    ends.tip_clamp_omega = external_load_ ? Eigen::Vector3d::Zero() : worldToPaper(angularVelocity(rotation, rate));
  }
  if (has_winch_) {
    const WinchMotion m = winch_.at(t);
    ends.winch = true;
    ends.winch_length = m.length - outboard_length_;
    ends.winch_deployed = m.length;
    ends.winch_speed = m.speed;
    ends.winch_acceleration = m.acceleration;
  }
  return ends;
}

void EndConditions::setLoadTarget(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity,
                                  const Eigen::Quaterniond& attitude, double time) {
  external_load_ = true;
  load_time_ = time;
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
  const Eigen::Matrix3d frame = worldToPaperRotation(base_attitude_.toRotationMatrix()) * rest_clamp_;
  external_clamp_twist_ = frameTwist(frame, external_clamp_twist_);  // continuous through whole turns
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
