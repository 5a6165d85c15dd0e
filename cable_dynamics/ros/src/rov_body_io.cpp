#include "cable_dynamics/ros/rov_body_io.h"

#include <cmath>

#include <tf2_eigen/tf2_eigen.h>

#include "cable_dynamics/dynamics/frames.h"
#include "cable_dynamics/params/format_values.h"
#include "cable_dynamics/params/input_gate.h"

namespace cable_dynamics {

void fillRovOdometry(const SimulationSnapshot& s, const Eigen::Vector3d& base_position, const ros::Time& stamp,
                     const std::string& world_frame, const std::string& rov_frame, nav_msgs::Odometry& out) {
  out.header.stamp = stamp;
  out.header.frame_id = world_frame;
  out.child_frame_id = rov_frame;
  // From the snapshot's paper frame to the world frame.
  out.pose.pose.position = tf2::toMsg(Eigen::Vector3d(paperToWorld(s.rov_origin) + base_position));
  out.pose.pose.orientation = tf2::toMsg(paperToWorldAttitude(s.rov_attitude));
  // The twist in the ROV's frame (REP-105's child frame).
  tf2::toMsg(Eigen::Vector3d(s.rov_attitude.conjugate() * s.rov_velocity), out.twist.twist.linear);
  tf2::toMsg(s.rov_angular_velocity, out.twist.twist.angular);
}

bool readThrust(const geometry_msgs::WrenchStamped& msg, const std::string& rov_frame, Eigen::Vector3d& force,
                Eigen::Vector3d& torque, std::string& why) {
  if (!msg.header.frame_id.empty() && msg.header.frame_id != rov_frame) {
    why = "frame '" + msg.header.frame_id + "': expected '" + rov_frame + "' (the ROV's own axes) or empty";
    return false;
  }
  force << msg.wrench.force.x, msg.wrench.force.y, msg.wrench.force.z;
  torque << msg.wrench.torque.x, msg.wrench.torque.y, msg.wrench.torque.z;
  if (!thrustAllowed(force) || !thrustAllowed(torque)) {
    why = "force " + formatVector(force) + ", torque " + formatVector(torque) + ": expected finite components within +-" +
          std::to_string(kMaxThrust);
    return false;
  }
  return true;
}

bool readBodyTarget(const geometry_msgs::PoseStamped& msg, const std::string& world_frame,
                    const Eigen::Vector3d& base_position, Eigen::Vector3d& position, Eigen::Quaterniond& attitude,
                    std::string& why) {
  if (!msg.header.frame_id.empty() && msg.header.frame_id != world_frame) {
    why = "frame '" + msg.header.frame_id + "': expected '" + world_frame + "' or empty";
    return false;
  }
  const auto& p = msg.pose.position;
  const auto& q = msg.pose.orientation;
  position = Eigen::Vector3d(p.x, p.y, p.z) - base_position;
  attitude = Eigen::Quaterniond(q.w, q.x, q.y, q.z);
  if (!positionAllowed(position) || !attitude.coeffs().allFinite() || std::abs(attitude.norm() - 1.0) > 1e-3) {
    why = "position " + formatVector(position) + ", orientation " + formatVector(attitude.coeffs()) +
          ": expected finite values and a unit quaternion";
    return false;
  }
  attitude.normalize();
  return true;
}

}  // namespace cable_dynamics
