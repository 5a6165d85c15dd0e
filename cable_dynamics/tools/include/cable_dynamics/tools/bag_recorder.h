#pragma once
/// \file
/// \brief cable_sim's `--bag run.bag`: the node's topics at every sample instant, stamped with the simulated
///        time, as a rosbag (rosbag_storage), so that `rosbag play --clock` and rviz replay an offline run.
///        The messages are the node's own: prepareOutputs / shapeOutputs / fill* of message_builders.h
///        from readOutputs, as CableNode::publishOutputs builds them. No roscore needed.

#include <memory>
#include <string>

#include <ros/time.h>

#include "cable_dynamics/tools/sample_recorder.h"

namespace cable_dynamics {

/// Where and how the bag's topics are named, as by `roslaunch cable_dynamics umbilical.launch` (its
/// defaults): topics under `/<ns>/`, frames and joints prefixed `<ns>/`, the world frame `world`.
struct BagLayout {
  std::string ns = "umbilical";      ///< the node's namespace (no slashes)
  std::string world_frame = "world";
  /// A bag's times must be later than ros::Time(0) (rosbag refuses 0, and tf and rviz read a zero stamp as
  /// "no time"): every stamp and bag time is this origin plus the simulated time [s].
  double time_origin = 1.0;
  /// The tension colour scale's top [N]: as the node's `ros.tension_scale`, 0 = the largest tension so far.
  double tension_scale = 0.0;
};

/// The topics written, below `/<ns>/` unless absolute: joint_states, cable_state, cable_markers, rov_wrench,
/// rov_wrench_world, base_wrench, base_wrench_world, /tf (the link frames and the two bodies' frames, one
/// tf2_msgs/TFMessage each per instant), and robot_description (std_msgs/String, latched, once at the start:
/// the node's parameter of that name, for rviz's RobotModel with Description Source "Topic").
/// /diagnostics is not written: its figures are the node's wall-clock loop, which an offline run has not.
class BagRecorder : public SampleRecorder {
 public:
  /// Opens `path` for writing; throws std::runtime_error naming it when it cannot.
  BagRecorder(const std::string& path, const CableParams& params, const BagLayout& layout = BagLayout());
  ~BagRecorder() override;
  bool record(CableSimulator& sim, std::string& error) override;
  bool close(std::string& error) override;

  /// The stamp of simulated time `t` [s].
  static ros::Time stampOf(double t, const BagLayout& layout) { return ros::Time(layout.time_origin + t); }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The factory cable_sim's main passes to runCableSim (the default layout).
SampleRecorderFactory bagRecorderFactory();

}  // namespace cable_dynamics
