#pragma once
/// \file
/// \brief The node's one clock: simulated time is the simulator's time(); this ties it to the ROS clock
///        (wall or /clock), says how much simulated time is due, stamps each simulated instant with the
///        ROS time it stands for, and bounds the lag. ROS-light (ros::Time), no roscore needed.

#include <ros/time.h>

namespace cable_dynamics {

/// Maps simulated time [s] to ROS time: stamp(t) = anchor_ros + (t - anchor_sim).
class SimClock {
 public:
  /// `max_lag` [s]: simulated time further behind the clock is dropped (dropExcessLag).
  explicit SimClock(double max_lag) : max_lag_(max_lag) {}

  /// Ties the simulated instant `sim_time` [s] to the ROS time `now`: at start, after a reset (the
  /// simulator's time back to 0), while paused (paused time is not simulated), and when the clock jumps
  /// back (/clock restarted).
  void anchor(const ros::Time& now, double sim_time);
  bool anchored() const { return anchored_; }

  /// Simulated time the clock asks for at `now` [s].
  double dueSimTime(const ros::Time& now) const { return anchor_sim_ + (now - anchor_ros_).toSec(); }
  /// How far the simulated time `sim_time` is behind the clock at `now` [s], >= 0.
  double lag(const ros::Time& now, double sim_time) const;
  /// ROS time that the simulated instant `sim_time` [s] stands for: the stamp of everything published of it.
  ros::Time stampOf(double sim_time) const { return anchor_ros_ + ros::Duration(sim_time - anchor_sim_); }

  /// When the lag exceeds max_lag, moves the anchor so that it equals max_lag: that much simulated time
  /// is given up (never simulated) so that stamps stay near the clock. Returns the seconds dropped.
  double dropExcessLag(const ros::Time& now, double sim_time);

 private:
  double max_lag_;
  bool anchored_ = false;
  ros::Time anchor_ros_;
  double anchor_sim_ = 0.0;
};

}  // namespace cable_dynamics
