#pragma once
/// \file
/// \brief The ROS adapter: parameters in, simulation stepped from a timer, topics, TF, markers,
///        diagnostics and services out. All physics lives in the ROS-free core.

#include <memory>
#include <string>
#include <vector>

#include <cable_msgs/CableState.h>
#include <cable_msgs/GetModel.h>
#include <cable_msgs/Reset.h>
#include <cable_msgs/SetPaused.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/TwistStamped.h>
#include <geometry_msgs/WrenchStamped.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>
#include <visualization_msgs/MarkerArray.h>

#include "cable_dynamics/simulation/cable_simulator.h"
#include "cable_dynamics/urdf/cable_urdf.h"
#include "cable_dynamics/dynamics/elastic_joints.h"
#include "cable_dynamics/simulation/link_frames.h"
#include "cable_dynamics/ros/node_options.h"

namespace cable_dynamics {

/// One simulated cable in one namespace.
class CableNode {
 public:
  /// Reads and validates parameters (throws ConfigError / std::invalid_argument naming the key), sets
  /// up topics, services, the URDF parameter and the timer.
  CableNode(ros::NodeHandle nh, ros::NodeHandle private_nh);

 private:
  void onTimer(const ros::TimerEvent& event);
  void onRovPose(const geometry_msgs::PoseStamped::ConstPtr& msg);
  void onBasePose(const geometry_msgs::PoseStamped::ConstPtr& msg);
  void onCurrent(const geometry_msgs::TwistStamped::ConstPtr& msg);
  bool onReset(cable_msgs::Reset::Request& req, cable_msgs::Reset::Response& res);
  bool onGetModel(cable_msgs::GetModel::Request& req, cable_msgs::GetModel::Response& res);
  bool onSetPaused(cable_msgs::SetPaused::Request& req, cable_msgs::SetPaused::Response& res);

  /// Checks stamp and frame of an input and gives its position in the world frame. Counts and logs
  /// rejections.
  bool acceptPose(const geometry_msgs::PoseStamped& msg, const char* topic, Eigen::Vector3d& world_position);
  bool fresh(const ros::Time& stamp, const char* topic);
  /// acceptPose, then a jump check and the velocity estimate; updates `tracked` when accepted.
  struct TrackedPose;
  bool trackPose(const geometry_msgs::PoseStamped& msg, const char* topic, TrackedPose& tracked);
  void publish(const ros::Time& stamp, double step_seconds);
  void publishDiagnostics(const ros::Time& stamp);
  void prepareMessages();
  void resynchronize();

  ros::NodeHandle nh_, private_nh_;
  CableParams params_;
  NodeOptions options_;
  CableFrameNames names_;
  std::unique_ptr<CableSimulator> sim_;
  std::unique_ptr<ElasticJoints> joints_;

  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  tf2_ros::TransformBroadcaster tf_broadcaster_;
  ros::Publisher joint_pub_, state_pub_, marker_pub_, wrench_pub_, diagnostics_pub_;
  ros::Subscriber rov_sub_, base_sub_, current_sub_;
  ros::ServiceServer reset_srv_, model_srv_, pause_srv_;
  ros::Timer timer_;

  // Preallocated outputs, written by index every cycle.
  sensor_msgs::JointState joint_msg_;
  cable_msgs::CableState state_msg_;
  visualization_msgs::MarkerArray marker_msg_;
  geometry_msgs::WrenchStamped wrench_msg_;
  std::vector<geometry_msgs::TransformStamped> transforms_;
  SimulationSnapshot snapshot_;
  PoseVector link_poses_, after_z_, after_x_;
  Eigen::VectorXd alpha_hint_, effort_;

  // Time keeping: simulated seconds since the last reset, against the ROS clock (wall or /clock).
  bool started_ = false, paused_ = false;
  ros::Time start_stamp_;
  long steps_done_ = 0;
  double lag_ = 0.0, real_time_factor_ = 0.0, step_seconds_ = 0.0, max_tension_seen_ = 1.0;
  ros::WallTime rate_window_start_;
  long rate_window_steps_ = 0, rate_window_cycles_ = 0;
  double loop_rate_ = 0.0;
  ros::Time last_diagnostics_, last_publish_;

  // Inputs: the last accepted pose of the ROV and of the base (world frame), and their velocity
  // estimated from successive poses.
  struct TrackedPose {
    bool valid = false;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< [m]
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  ///< [m/s]
    ros::Time stamp;
  };
  TrackedPose rov_, base_;
  unsigned rejected_ = 0, stale_ = 0, diverged_ = 0;
};

}  // namespace cable_dynamics
