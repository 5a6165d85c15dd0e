#pragma once
/// \file
/// \brief Follows one pose stream (ROV or base): plausibility of the first pose, jump check with a
///        minimum interval, velocity estimate, and re-acquisition so that it never locks out. ROS-light
///        (ros::Time only), no roscore needed.

#include <Eigen/Core>
#include <ros/time.h>

#include "cable_dynamics/ros/input_verdict.h"

namespace cable_dynamics {

/// Limits of a PoseTracker.
struct TrackerLimits {
  double max_speed = 20.0;          ///< a pose implying a faster motion is a jump [m/s]
  double min_interval = 0.01;       ///< shortest interval the jump check divides by [s]
  double plausible_radius = 100.0;  ///< every pose must be this close to the expected centre [m]
  int reacquire_after = 10;         ///< this many consecutive consistent refused poses form a new stream
};

/// The last accepted position of a stream and its velocity estimate.
class PoseTracker {
 public:
  explicit PoseTracker(const TrackerLimits& limits) : limits_(limits) {}

  /// Judges a finite world position [m] stamped `stamp` (effective: the receiver's clock for an unstamped
  /// message). Every pose must lie within plausible_radius of `centre` [m] (beyond it none is taken and
  /// none counts towards a new stream); later ones must not move
  /// faster than max_speed over max(interval, min_interval). A refused pose that is consistent with the
  /// refused one before it (within the same speed limit) extends a streak; at reacquire_after the tracker
  /// takes it as its new position (kReacquired). Updates the position and velocity when accepted.
  InputVerdict judge(const Eigen::Vector3d& position, const ros::Time& stamp, const Eigen::Vector3d& centre);

  /// Forgets the stream: the next pose is a first pose again.
  void forget();

  bool valid() const { return valid_; }
  const Eigen::Vector3d& position() const { return position_; }  ///< [m], world frame
  const Eigen::Vector3d& velocity() const { return velocity_; }  ///< [m/s], world frame

 private:
  bool withinSpeed(const Eigen::Vector3d& from, const ros::Time& from_stamp, const Eigen::Vector3d& to,
                   const ros::Time& to_stamp) const;
  InputVerdict refuse(const Eigen::Vector3d& position, const ros::Time& stamp, InputVerdict why);
  void take(const Eigen::Vector3d& position, const ros::Time& stamp, const Eigen::Vector3d& velocity);

  TrackerLimits limits_;
  bool valid_ = false;
  Eigen::Vector3d position_ = Eigen::Vector3d::Zero(), velocity_ = Eigen::Vector3d::Zero();
  ros::Time stamp_;
  int streak_ = 0;  ///< consecutive consistent refused poses, the last one in candidate_
  Eigen::Vector3d candidate_ = Eigen::Vector3d::Zero();
  ros::Time candidate_stamp_;
};

}  // namespace cable_dynamics
