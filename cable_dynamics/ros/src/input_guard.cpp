#include "cable_dynamics/ros/input_guard.h"

#include <cmath>

#include "cable_dynamics/ros/frame_name.h"

namespace cable_dynamics {
namespace {

TrackerLimits trackerLimits(const GuardSettings& s) {
  TrackerLimits limits;
  limits.max_speed = kMaxInputSpeed;
  limits.min_interval = kMinJumpInterval;
  limits.plausible_radius = s.plausible_radius;
  limits.reacquire_after = kReacquireAfter;
  return limits;
}

bool finite(const geometry_msgs::Pose& p) {
  return std::isfinite(p.position.x) && std::isfinite(p.position.y) && std::isfinite(p.position.z) &&
         std::isfinite(p.orientation.x) && std::isfinite(p.orientation.y) && std::isfinite(p.orientation.z) &&
         std::isfinite(p.orientation.w);
}

bool finite(const geometry_msgs::Twist& t) {
  return std::isfinite(t.linear.x) && std::isfinite(t.linear.y) && std::isfinite(t.linear.z) &&
         std::isfinite(t.angular.x) && std::isfinite(t.angular.y) && std::isfinite(t.angular.z);
}

/// The raw message's position, before the frame's transform (a finite number beyond it is no pose).
bool inRange(const Eigen::Vector3d& p) { return p.cwiseAbs().maxCoeff() <= kMaxInputPosition; }

}  // namespace

InputGuard::InputGuard(const GuardSettings& settings)
    : settings_(settings), trackers_{PoseTracker(trackerLimits(settings)), PoseTracker(trackerLimits(settings))} {}

InputVerdict InputGuard::frameTransform(const std::string& frame_id, const FrameResolver& resolve,
                                        Eigen::Isometry3d& t) const {
  t.setIdentity();
  if (frame_id.empty() || frame_id == settings_.world_frame) return InputVerdict::kAccepted;
  // A bad name never reaches tf2, which would print a warning for each such message.
  if (!isValidFrameName(frame_id) || !resolve(frame_id, t)) return InputVerdict::kBadFrame;
  return InputVerdict::kAccepted;
}

InputVerdict InputGuard::checkStamp(Topic topic, const ros::Time& stamp, const ros::Time& now) {
  Stream& s = streams_[topic];
  // A stream silent for longer than the timeout (or a clock that went back) is a new stream: its order
  // and its tracker start again, so that no old state can lock the input out.
  if (s.active && (now < s.accepted_at || (now - s.accepted_at).toSec() > settings_.input_timeout)) {
    s = Stream();
    if (topic != kCurrent) trackers_[topic].forget();
  }
  if (stamp.isZero()) return InputVerdict::kAccepted;  // an unstamped message means "now"
  const double age = (now - stamp).toSec();
  if (std::abs(age) > settings_.input_timeout) return InputVerdict::kStale;
  if (s.has_stamp && stamp <= s.last_stamp) return InputVerdict::kOutOfOrder;
  return InputVerdict::kAccepted;
}

InputVerdict InputGuard::settle(Topic topic, InputVerdict verdict, const ros::Time& stamp, const ros::Time& now) {
  if (isAccepted(verdict)) {
    Stream& s = streams_[topic];
    s.active = true;
    s.accepted_at = now;
    if (!stamp.isZero()) {
      s.has_stamp = true;
      s.last_stamp = stamp;
    }
  } else if (isStale(verdict)) {
    ++counters_.stale;
  } else {
    ++counters_.rejected;
  }
  return verdict;
}

InputVerdict InputGuard::pose(Topic topic, const geometry_msgs::PoseStamped& msg, const ros::Time& now,
                              const FrameResolver& resolve, Eigen::Vector3d& position, Eigen::Vector3d& velocity,
                              Eigen::Quaterniond& attitude) {
  ++counters_.received;
  const ros::Time& stamp = msg.header.stamp;
  if (!finite(msg.pose)) return settle(topic, InputVerdict::kNonFinite, stamp, now);
  const Eigen::Vector3d raw(msg.pose.position.x, msg.pose.position.y, msg.pose.position.z);
  if (!inRange(raw)) return settle(topic, InputVerdict::kOutOfRange, stamp, now);
  Eigen::Isometry3d world_from_frame;
  const InputVerdict frame = frameTransform(msg.header.frame_id, resolve, world_from_frame);
  if (!isAccepted(frame)) return settle(topic, frame, stamp, now);
  const geometry_msgs::Quaternion& o = msg.pose.orientation;
  Eigen::Quaterniond in_frame(o.w, o.x, o.y, o.z);
  const double norm = in_frame.coeffs().stableNorm();  // no overflow for huge (finite) entries
  if (!(norm > 1e-9)) {
    in_frame = Eigen::Quaterniond::Identity();  // an unset orientation: no rotation
  } else {
    in_frame.coeffs() /= norm;
  }
  const Eigen::Vector3d& body_point = topic == kRovPose ? settings_.rov_attachment : settings_.base_hang_off;
  const Eigen::Vector3d world = world_from_frame * (raw + in_frame * body_point);
  // What the node hands the simulator: the position from the base's rest position (the gate's range).
  if (!positionAllowed(world - settings_.base_rest)) return settle(topic, InputVerdict::kOutOfRange, stamp, now);
  attitude = Eigen::Quaterniond(world_from_frame.linear()) * in_frame;
  const InputVerdict timing = checkStamp(topic, stamp, now);
  if (!isAccepted(timing)) return settle(topic, timing, stamp, now);
  // The ROV's first pose is judged against the base's position; the base's against its rest position.
  PoseTracker& tracker = trackers_[topic];
  const PoseTracker& base = trackers_[kBasePose];
  const Eigen::Vector3d centre = topic == kRovPose && base.valid() ? base.position() : settings_.base_rest;
  const InputVerdict verdict = tracker.judge(world, stamp.isZero() ? now : stamp, centre);
  position = tracker.position();
  velocity = tracker.velocity();
  return settle(topic, verdict, stamp, now);
}

InputVerdict InputGuard::current(const geometry_msgs::TwistStamped& msg, const ros::Time& now,
                                 const FrameResolver& resolve, Eigen::Vector3d& current) {
  ++counters_.received;
  const ros::Time& stamp = msg.header.stamp;
  if (!finite(msg.twist)) return settle(kCurrent, InputVerdict::kNonFinite, stamp, now);
  const Eigen::Vector3d raw(msg.twist.linear.x, msg.twist.linear.y, msg.twist.linear.z);
  Eigen::Isometry3d world_from_frame;
  const InputVerdict frame = frameTransform(msg.header.frame_id, resolve, world_from_frame);
  if (!isAccepted(frame)) return settle(kCurrent, frame, stamp, now);
  // In world axes, as the simulator takes it: the gate's range (fluid.current's).
  const Eigen::Vector3d world = world_from_frame.linear() * raw;  // a velocity: rotated, not translated
  if (!currentAllowed(world)) return settle(kCurrent, InputVerdict::kOutOfRange, stamp, now);
  const InputVerdict timing = checkStamp(kCurrent, stamp, now);
  if (!isAccepted(timing)) return settle(kCurrent, timing, stamp, now);
  current = world;
  return settle(kCurrent, InputVerdict::kAccepted, stamp, now);
}

InputVerdict InputGuard::winchSpeed(const std_msgs::Float64& msg, double& speed) {
  ++counters_.received;
  InputVerdict verdict = InputVerdict::kAccepted;
  if (!settings_.winch) {
    verdict = InputVerdict::kNoWinch;
  } else if (!std::isfinite(msg.data)) {
    verdict = InputVerdict::kNonFinite;
  } else if (!winchSpeedAllowed(msg.data, settings_.winch_max_speed)) {  // the gate's check
    verdict = InputVerdict::kOutOfRange;
  }
  if (isAccepted(verdict)) {
    speed = msg.data;
  } else {
    ++counters_.rejected;
  }
  return verdict;
}

}  // namespace cable_dynamics
