#pragma once
/// \file
/// \brief The ROS adapter's I/O: parameters in, subscriptions through the input guard, a timer that steps
///        the simulator on the node's clock, the messages published, the services. The physics lives in the
///        ROS-free core; the checks, the clock and the message filling live in their own files.

#include <memory>

#include <cable_msgs/CouplingPort.h>
#include <cable_msgs/GetModel.h>
#include <cable_msgs/Reset.h>
#include <cable_msgs/ResetToEquilibrium.h>
#include <cable_msgs/SetPaused.h>
#include <cable_msgs/SetWinchLength.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TwistStamped.h>
#include <ros/ros.h>
#include <std_msgs/Float64.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>

#include "cable_dynamics/ros/coupling_sizer.h"
#include "cable_dynamics/ros/rov_body_io.h"
#include "cable_dynamics/ros/input_guard.h"
#include "cable_dynamics/ros/live_tuning.h"
#include "cable_dynamics/ros/message_builders.h"
#include "cable_dynamics/ros/node_options.h"
#include "cable_dynamics/ros/output_source.h"
#include "cable_dynamics/ros/rate_window.h"
#include "cable_dynamics/ros/shared_publisher.h"
#include "cable_dynamics/ros/sim_clock.h"
#include "cable_dynamics/simulation/cable_simulator.h"
#include "cable_dynamics/urdf/cable_urdf.h"

namespace cable_dynamics {

/// One simulated cable in one namespace: the standalone node (cable_dynamics_node_main.cpp) and the
/// nodelet (cable_nodelet.cpp) both run one of these on the node handles they are given.
class CableNode {
 public:
  /// Reads and validates parameters (throws ConfigError / std::invalid_argument naming the key), sets up
  /// topics, services, the URDF parameter, the live-tuning server (`~tuning`) and the timer.
  CableNode(ros::NodeHandle nh, ros::NodeHandle private_nh);

 private:
  void onTimer(const ros::TimerEvent& event);
  void onRovPose(const geometry_msgs::PoseStamped::ConstPtr& msg);
  void onBasePose(const geometry_msgs::PoseStamped::ConstPtr& msg);
  void onCurrent(const geometry_msgs::TwistStamped::ConstPtr& msg);
  bool onReset(cable_msgs::Reset::Request& req, cable_msgs::Reset::Response& res);
  bool onResetToEquilibrium(cable_msgs::ResetToEquilibrium::Request& req, cable_msgs::ResetToEquilibrium::Response& res);
  bool onGetModel(cable_msgs::GetModel::Request& req, cable_msgs::GetModel::Response& res);
  bool onSetPaused(cable_msgs::SetPaused::Request& req, cable_msgs::SetPaused::Response& res);
  void onWinchSpeed(const std_msgs::Float64::ConstPtr& msg);
  bool onSetWinchLength(cable_msgs::SetWinchLength::Request& req, cable_msgs::SetWinchLength::Response& res);

  /// tf2 lookup of a frame in the world frame, without waiting and without tf2's own warnings.
  bool resolveFrame(const std::string& frame, Eigen::Isometry3d& world_from_frame);
  /// Reads the present state and publishes every output stamped `stamp`; on a non-finite state recovers
  /// the simulator and publishes nothing.
  void publishOutputs(const ros::Time& stamp);
  /// Live tuning (live_tuning.h): applies each changed part of `wanted` that passes its check, logs each
  /// refusal (key, value, range) and returns the values in force.
  TunableValues applyTuning(const TunableValues& wanted, unsigned levels);
  /// Pauses or resumes (the set_paused service and live tuning).
  void setPaused(bool paused);
  /// A current message was accepted within ros.input_timeout: the topic, not the tuning, sets the current.
  bool currentTopicActive() const;
  /// After the simulator's time was set back to 0 (reset service).
  void restartClock();
  /// Retunes the simulator with the coupling the sizer holds (the configured one, or softer) and logs it.
  void applyCouplingSize();
  /// Counts a divergence and recovers the simulator (initial shape; time and inputs carry on).
  void recoverFromDivergence(const std::string& why);

  ros::NodeHandle nh_, private_nh_;
  CableParams params_;
  NodeOptions options_;
  CableFrameNames names_;
  std::unique_ptr<CableSimulator> sim_;
  std::unique_ptr<InputGuard> guard_;
  FrameResolver resolver_;

  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  tf2_ros::TransformBroadcaster tf_broadcaster_;
  // Shared pointers out: in a nodelet manager, subscribers there get the messages without copies.
  SharedPublisher<sensor_msgs::JointState> joint_pub_;
  SharedPublisher<cable_msgs::CableState> state_pub_;
  SharedPublisher<visualization_msgs::MarkerArray> marker_pub_;
  SharedPublisher<geometry_msgs::WrenchStamped> wrench_pub_, wrench_world_pub_, base_wrench_pub_, base_wrench_world_pub_;
  /// rov_coupling (attached loads only): the ROV's port with its stiffness and damping.
  SharedPublisher<cable_msgs::CouplingPort> port_pub_;
  cable_msgs::CouplingPort port_msg_;
  /// An attached load's coupling sized for the pose exchange (null when not attached or ros.min_rov_mass 0).
  std::unique_ptr<CouplingSizer> sizer_;
  ros::Publisher diagnostics_pub_;
  ros::Publisher seabed_pub_, contact_pub_;  ///< with a seabed: the bottom (latched), the links on it
  visualization_msgs::Marker contact_marker_;
  ros::Subscriber rov_sub_, base_sub_, current_sub_, winch_sub_;
  /// The last accepted ROV and vessel poses (from the base's rest position), put back after a `reset`
  /// when their stream is live (accepted within ros.input_timeout): a reset restarts the cable, not the
  /// world around it.
  struct HeldPose {
    bool known = false;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    Eigen::Quaterniond attitude = Eigen::Quaterniond::Identity();
    ros::Time received;
  };
  HeldPose last_rov_pose_, last_base_pose_;
  /// After a reset: the live streams' last poses back in the simulator, at rest, at its time 0.
  void restoreLivePoses();
  // An ROV body simulated here (load.mode body): thrust and station-keeping target in, odometry out.
  ros::Subscriber thrust_sub_, target_sub_;
  SharedPublisher<nav_msgs::Odometry> odom_pub_;
  nav_msgs::Odometry odom_msg_;
  ros::Time last_thrust_;        ///< the last accepted rov_thrust; zero before the first
  bool thrust_held_ = false;     ///< a commanded thrust is in force (zeroed when its stream goes stale)
  unsigned long thrust_rejected_ = 0, thrust_stale_ = 0, target_rejected_ = 0;
  unsigned long body_received_ = 0;  ///< rov_thrust and rov_target messages, valid or not
  void onRovThrust(const geometry_msgs::WrenchStamped::ConstPtr& msg);
  void onRovTarget(const geometry_msgs::PoseStamped::ConstPtr& msg);
  /// A thrust stream silent for ros.input_timeout: its thrust is dropped (thrusters off), counted once.
  void dropStaleThrust(const ros::Time& now);
  ros::ServiceServer reset_srv_, equilibrium_srv_, model_srv_, pause_srv_, winch_srv_;
  ros::Timer timer_;

  // Live tuning: the config tree and the `ros` section as read at start (with the tuned values since),
  // from which each request is checked by the config loader; the values in force.
  YAML::Node config_tree_, ros_tree_;
  TunableValues tuned_;
  bool current_tuned_ = false;        ///< the tuned current replaces the configured one (also after reset)
  ros::Time last_current_accepted_;   ///< of the current topic; zero before the first
  std::unique_ptr<LiveTuning> tuning_;
  /// A topic (current, winch/speed) changed a value the tuning server shows: shown at most every
  /// kShowPeriod (each show sets parameters on the master), the last change always.
  void showInForce(bool changed);
  static constexpr double kShowPeriod = 0.2;  ///< [s] of wall time
  ros::WallTime last_show_;
  bool show_pending_ = false;

  CableOutputs outputs_;  ///< preallocated, written by index every cycle
  OutputSource source_;
  NodeStatus status_;
  SimClock clock_;
  RateWindow window_;
  ros::Time last_now_, last_stamp_, last_diagnostics_;
  double max_tension_seen_ = 1.0;  ///< [N], colour scale when ros.tension_scale is 0
  unsigned diverged_at_diagnostics_ = 0;
  double dropped_at_diagnostics_ = 0.0;
};

}  // namespace cable_dynamics
