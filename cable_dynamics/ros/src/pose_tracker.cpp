#include "cable_dynamics/ros/pose_tracker.h"

#include <algorithm>

namespace cable_dynamics {

bool PoseTracker::withinSpeed(const Eigen::Vector3d& from, const ros::Time& from_stamp, const Eigen::Vector3d& to,
                              const ros::Time& to_stamp) const {
  // A minimum interval: two poses stamped (nearly) alike cannot make any distance look slow.
  const double interval = std::max((to_stamp - from_stamp).toSec(), limits_.min_interval);
  return (to - from).norm() <= limits_.max_speed * interval;
}

InputVerdict PoseTracker::judge(const Eigen::Vector3d& position, const ros::Time& stamp,
                                const Eigen::Vector3d& centre) {
  // Beyond the radius no pose is taken, first or not, and no run of them starts a new stream: a stream the
  // cable cannot reach would drive the coupling to any force (issue 27: 10 km poses, 2e8 N).
  if ((position - centre).norm() > limits_.plausible_radius) {
    streak_ = 0;
    return InputVerdict::kImplausible;
  }
  if (!valid_) {
    take(position, stamp, Eigen::Vector3d::Zero());
    return InputVerdict::kAccepted;
  }
  if (!withinSpeed(position_, stamp_, position, stamp)) return refuse(position, stamp, InputVerdict::kJump);
  const double interval = std::max((stamp - stamp_).toSec(), limits_.min_interval);
  take(position, stamp, (position - position_) / interval);
  return InputVerdict::kAccepted;
}

InputVerdict PoseTracker::refuse(const Eigen::Vector3d& position, const ros::Time& stamp, InputVerdict why) {
  const bool consistent = streak_ > 0 && withinSpeed(candidate_, candidate_stamp_, position, stamp);
  streak_ = consistent ? streak_ + 1 : 1;
  candidate_ = position;
  candidate_stamp_ = stamp;
  if (streak_ < limits_.reacquire_after) return why;
  // The stream really is somewhere else (the ROV was moved, or the first poses were far): follow it
  // rather than refuse every pose from now on.
  take(position, stamp, Eigen::Vector3d::Zero());
  return InputVerdict::kReacquired;
}

void PoseTracker::take(const Eigen::Vector3d& position, const ros::Time& stamp, const Eigen::Vector3d& velocity) {
  valid_ = true;
  position_ = position;
  velocity_ = velocity;
  stamp_ = stamp;
  streak_ = 0;
}

void PoseTracker::forget() {
  valid_ = false;
  velocity_.setZero();
  streak_ = 0;
}

}  // namespace cable_dynamics
