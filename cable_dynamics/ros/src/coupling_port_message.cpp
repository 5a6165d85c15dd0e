#include "cable_dynamics/ros/coupling_port_message.h"

#include <cmath>

namespace cable_dynamics {

namespace {

template <class Message>
void setXyz(const Eigen::Vector3d& v, Message& m) {
  m.x = v.x();
  m.y = v.y();
  m.z = v.z();
}

}  // namespace

void fillCouplingPort(const CouplingPort& paper, const Eigen::Vector3d& base_position, const ros::Time& stamp,
                      cable_msgs::CouplingPort& msg) {
  msg.header.stamp = stamp;
  const CouplingPort port = portInWorldAxes(paper);  // the snapshot's paper frame to the world frame
  setXyz(port.point + base_position, msg.point);
  setXyz(port.velocity, msg.velocity);
  setXyz(port.force, msg.wrench.force);
  setXyz(port.moment, msg.wrench.torque);
  for (int r = 0; r < 6; ++r) {
    for (int c = 0; c < 6; ++c) {
      msg.stiffness[6 * r + c] = port.stiffness(r, c);
      msg.damping[6 * r + c] = port.damping(r, c);
    }
  }
}

bool allFinite(const cable_msgs::CouplingPort& msg) {
  const double xyz[] = {msg.point.x,          msg.point.y,          msg.point.z,          msg.velocity.x,
                        msg.velocity.y,       msg.velocity.z,       msg.wrench.force.x,   msg.wrench.force.y,
                        msg.wrench.force.z,   msg.wrench.torque.x,  msg.wrench.torque.y,  msg.wrench.torque.z};
  for (double v : xyz) {
    if (!std::isfinite(v)) return false;
  }
  for (int i = 0; i < 36; ++i) {
    if (!std::isfinite(msg.stiffness[i]) || !std::isfinite(msg.damping[i])) return false;
  }
  return true;
}

}  // namespace cable_dynamics
