#include "cable_dynamics/ros/finite_messages.h"

#include <cmath>

namespace cable_dynamics {
namespace {

bool finite(const std::vector<double>& v) {
  for (double x : v) {
    if (!std::isfinite(x)) return false;
  }
  return true;
}

bool finite(const geometry_msgs::Vector3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(const geometry_msgs::Point& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }
bool finite(const geometry_msgs::Quaternion& q) {
  return std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z) && std::isfinite(q.w);
}
bool finite(const std_msgs::ColorRGBA& c) {
  return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b) && std::isfinite(c.a);
}

}  // namespace

bool allFinite(const sensor_msgs::JointState& msg) {
  return finite(msg.position) && finite(msg.velocity) && finite(msg.effort);
}

bool allFinite(const std::vector<geometry_msgs::TransformStamped>& transforms) {
  for (const auto& t : transforms) {
    if (!finite(t.transform.translation) || !finite(t.transform.rotation)) return false;
  }
  return true;
}

bool allFinite(const visualization_msgs::MarkerArray& msg) {
  for (const auto& m : msg.markers) {
    if (!finite(m.pose.position) || !finite(m.pose.orientation) || !finite(m.scale) || !finite(m.color)) return false;
    for (const auto& p : m.points) {
      if (!finite(p)) return false;
    }
    for (const auto& c : m.colors) {
      if (!finite(c)) return false;
    }
  }
  return true;
}

bool allFinite(const cable_msgs::CableState& msg) {
  return finite(msg.tension) && std::isfinite(msg.top_tension) && finite(msg.load_force) && finite(msg.base_force) &&
         std::isfinite(msg.kinetic_energy) && std::isfinite(msg.potential_energy) &&
         std::isfinite(msg.elastic_energy) && std::isfinite(msg.dissipated_energy) && std::isfinite(msg.sim_time) &&
         std::isfinite(msg.step_time) && std::isfinite(msg.real_time_factor) && std::isfinite(msg.lag) &&
         std::isfinite(msg.deployed_length) && std::isfinite(msg.line_pull) && std::isfinite(msg.winch_speed) &&
         std::isfinite(msg.grounded_length) && std::isfinite(msg.touchdown_arc_length) && finite(msg.touchdown) &&
         std::isfinite(msg.max_penetration) && std::isfinite(msg.contact_energy) && finite(msg.seabed_force) &&
         finite(msg.strain) && std::isfinite(msg.max_tension) && finite(msg.bend_radius) && finite(msg.utilisation) &&
         std::isfinite(msg.max_utilisation) && std::isfinite(msg.min_bend_radius);
}

bool allFinite(const geometry_msgs::WrenchStamped& msg) {
  return finite(msg.wrench.force) && finite(msg.wrench.torque);
}

bool allFinite(const NodeStatus& s) {
  return std::isfinite(s.sim_time) && std::isfinite(s.step_time) && std::isfinite(s.lag) &&
         std::isfinite(s.dropped_time) && std::isfinite(s.real_time_factor) && std::isfinite(s.loop_rate) &&
         std::isfinite(s.retried_share) && std::isfinite(s.winch.deployed_length) && std::isfinite(s.winch.speed) &&
         std::isfinite(s.winch.line_pull) && std::isfinite(s.winch.commanded_speed) &&
         std::isfinite(s.winch.target_length) && std::isfinite(s.limits.max_utilisation) &&
         std::isfinite(s.limits.min_bend_radius) && std::isfinite(s.limits.tension_utilisation) &&
         std::isfinite(s.limits.bend_utilisation) && std::isfinite(s.limits.seabed_clearance);
}

bool allFinite(const CableOutputs& o) {
  return allFinite(o.joints) && allFinite(o.transforms) && allFinite(o.markers) && allFinite(o.state) &&
         allFinite(o.wrench) && allFinite(o.wrench_world) && allFinite(o.base_wrench) &&
         allFinite(o.base_wrench_world) && allFinite(o.body_transforms);
}

}  // namespace cable_dynamics
