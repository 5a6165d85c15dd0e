#pragma once
/// \file
/// \brief Guards the node's inputs (rov_pose, base_pose, current, winch/speed) in one place: finiteness,
///        range, frame, freshness (stale and future stamps), order, plausibility and jumps; counts what it
///        refuses.
///        ROS-light (message structs and ros::Time; the tf2 lookup is passed in), no roscore needed.

#include <functional>
#include <string>

#include <Eigen/Geometry>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TwistStamped.h>
#include <ros/time.h>
#include <std_msgs/Float64.h>

#include "cable_dynamics/params/input_gate.h"
#include "cable_dynamics/ros/input_verdict.h"
#include "cable_dynamics/ros/pose_tracker.h"

namespace cable_dynamics {

// The limits on input values (kMaxInputPosition, kMaxInputSpeed, kMaxCurrentSpeed) are the simulator's
// gate's (params/input_gate.h): the guard refuses what the simulator's setters would refuse.
/// The jump check divides by at least this interval, whatever the stamps say [s].
constexpr double kMinJumpInterval = 0.01;
/// Consecutive consistent refused poses after which the tracker takes the new stream.
constexpr int kReacquireAfter = 10;

/// Places a frame in the world frame: returns false when it cannot (unknown frame, no transform yet).
/// Only called with a valid frame name other than the world frame.
using FrameResolver = std::function<bool(const std::string& frame, Eigen::Isometry3d& world_from_frame)>;

/// Settings of an InputGuard.
struct GuardSettings {
  std::string world_frame = "world";  ///< frame_id meaning "already in the world frame" (as does "")
  double input_timeout = 1.0;         ///< stamps further than this from the clock, either way, are stale [s]
  Eigen::Vector3d base_rest = Eigen::Vector3d::Zero();  ///< the base's rest position, world frame [m]
  double plausible_radius = 100.0;  ///< every pose must be this close to the base (rov) or its rest (base) [m]
  /// The points of the bodies the cable's ends are fixed to, in each body's frame [m]: the ROV's
  /// attachment (load.attachment) and the vessel's hang-off point (base.hang_off). A pose stream is
  /// tracked at that point of its body, so that its velocity holds the body's rotation too.
  Eigen::Vector3d rov_attachment = Eigen::Vector3d::Zero();
  Eigen::Vector3d base_hang_off = Eigen::Vector3d::Zero();
  bool winch = false;               ///< a winch is configured: winch/speed commands are taken
  double winch_max_speed = 0.0;     ///< winch.max_speed: faster commands are rejected [m/s]
};

/// Counters since start.
struct InputCounters {
  unsigned received = 0;  ///< every message handed to the guard
  unsigned rejected = 0;  ///< refused for any reason but staleness
  unsigned stale = 0;     ///< stamped more than input_timeout before or after the clock
};

/// The three input streams and their guards.
class InputGuard {
 public:
  enum Topic { kRovPose = 0, kBasePose = 1, kCurrent = 2 };

  explicit InputGuard(const GuardSettings& settings);

  /// Judges a pose message received at `now` (the ROS clock). When accepted, `position` [m] and
  /// `velocity` [m/s] are the world position and velocity estimate of the body's point (the ROV's
  /// attachment, the vessel's hang-off point), and `attitude` the body's orientation in the world frame
  /// (an all-zero quaternion reads as no rotation; any other is normalized).
  InputVerdict pose(Topic topic, const geometry_msgs::PoseStamped& msg, const ros::Time& now,
                    const FrameResolver& resolve, Eigen::Vector3d& position, Eigen::Vector3d& velocity,
                    Eigen::Quaterniond& attitude);
  /// Judges a current message; when accepted, `current` is its linear part in world axes [m/s].
  InputVerdict current(const geometry_msgs::TwistStamped& msg, const ros::Time& now, const FrameResolver& resolve,
                       Eigen::Vector3d& current);

  /// Judges a winch speed command [m/s, + pays out] (no stamp: no freshness or order rules). Rejected
  /// without a winch (kNoWinch), when not finite, or beyond winch_max_speed either way (kOutOfRange: a
  /// command the winch cannot follow is refused, not clamped). When accepted, `speed` is the command.
  InputVerdict winchSpeed(const std_msgs::Float64& msg, double& speed);

  const InputCounters& counters() const { return counters_; }
  const GuardSettings& settings() const { return settings_; }

 private:
  /// What the guard remembers of one topic.
  struct Stream {
    bool has_stamp = false;  ///< a stamped message was accepted: later ones must be newer
    ros::Time last_stamp;    ///< its stamp
    bool active = false;     ///< a message was accepted ...
    ros::Time accepted_at;   ///< ... at this time of the clock
  };

  /// Frame of `frame_id` in the world frame, or kBadFrame.
  InputVerdict frameTransform(const std::string& frame_id, const FrameResolver& resolve, Eigen::Isometry3d& t) const;
  /// Staleness and order of a stamp; forgets a stream silent for longer than the timeout.
  InputVerdict checkStamp(Topic topic, const ros::Time& stamp, const ros::Time& now);
  /// Counts the verdict and, when accepted, remembers the stamp.
  InputVerdict settle(Topic topic, InputVerdict verdict, const ros::Time& stamp, const ros::Time& now);

  GuardSettings settings_;
  InputCounters counters_;
  Stream streams_[3];
  PoseTracker trackers_[2];  ///< rov, base
};

}  // namespace cable_dynamics
