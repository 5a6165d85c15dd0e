#pragma once
// Test helper: subscribes to every output of one cable node and checks every number of every message it
// receives (joint_states, cable_state, cable_markers, rov_wrench, /tf, /diagnostics).
#include <cmath>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include <cable_msgs/CableState.h>
#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/WrenchStamped.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <tf2_msgs/TFMessage.h>
#include <visualization_msgs/MarkerArray.h>

namespace cable_test {

/// Latest outputs, counts, and the first non-finite number seen (where it was).
class OutputRecorder {
 public:
  /// `ns`: the node's namespace ("/hostile"); `diagnostics_name`: the status name to keep.
  OutputRecorder(ros::NodeHandle& nh, const std::string& ns, const std::string& diagnostics_name)
      : diagnostics_name_(diagnostics_name) {
    const uint32_t queue = 1000;
    subs_.push_back(nh.subscribe(ns + "/joint_states", queue, &OutputRecorder::onJoints, this));
    subs_.push_back(nh.subscribe(ns + "/cable_state", queue, &OutputRecorder::onState, this));
    subs_.push_back(nh.subscribe(ns + "/cable_markers", queue, &OutputRecorder::onMarkers, this));
    subs_.push_back(nh.subscribe(ns + "/rov_wrench", queue, &OutputRecorder::onWrench, this));
    subs_.push_back(nh.subscribe("/tf", queue, &OutputRecorder::onTf, this));
    subs_.push_back(nh.subscribe("/diagnostics", queue, &OutputRecorder::onDiagnostics, this));
  }

  sensor_msgs::JointState joints;
  cable_msgs::CableState state;
  visualization_msgs::MarkerArray markers;
  geometry_msgs::WrenchStamped wrench;
  diagnostic_msgs::DiagnosticStatus diagnostics;
  long joint_count = 0, state_count = 0, marker_count = 0, wrench_count = 0, tf_count = 0, diagnostics_count = 0;
  long numbers_checked = 0;
  std::string non_finite;        ///< where the first non-finite number was ("" = none)
  double peak_force = 0.0;       ///< largest |wrench force| received [N]
  double peak_joint_rate = 0.0;  ///< largest |joint velocity| received [rad/s], of states stamped after:
  ros::Time peak_joint_rate_after;  ///< (zero: all) a subscriber queue may still hold older states
  /// Largest cable_state.kinetic_energy of the states stamped after peak_joint_rate_after [J]: unlike a
  /// joint rate (the paper's azimuth rate grows without bound near the vertical), no coordinate's choice.
  double peak_kinetic_energy = 0.0;

  bool allReceived() const {
    return joint_count > 0 && state_count > 0 && marker_count > 0 && wrench_count > 0 && tf_count > 0;
  }

 private:
  void check(double v, const char* where) {
    ++numbers_checked;
    if (!std::isfinite(v) && non_finite.empty()) non_finite = where;
  }
  void check(const geometry_msgs::Vector3& v, const char* where) {
    check(v.x, where);
    check(v.y, where);
    check(v.z, where);
  }
  void check(const geometry_msgs::Point& v, const char* where) {
    check(v.x, where);
    check(v.y, where);
    check(v.z, where);
  }
  void check(const geometry_msgs::Quaternion& q, const char* where) {
    check(q.x, where);
    check(q.y, where);
    check(q.z, where);
    check(q.w, where);
  }

  void onJoints(const sensor_msgs::JointState& m) {
    for (double v : m.position) check(v, "joint_states.position");
    for (double v : m.velocity) {
      check(v, "joint_states.velocity");
      if (m.header.stamp > peak_joint_rate_after) peak_joint_rate = std::max(peak_joint_rate, std::abs(v));
    }
    for (double v : m.effort) check(v, "joint_states.effort");
    joints = m;
    ++joint_count;
  }
  void onState(const cable_msgs::CableState& m) {
    for (double v : m.tension) check(v, "cable_state.tension");
    for (double v : {m.top_tension, m.kinetic_energy, m.potential_energy, m.elastic_energy, m.dissipated_energy,
                     m.sim_time, m.step_time, m.real_time_factor, m.lag}) {
      check(v, "cable_state scalar");
    }
    check(m.load_force, "cable_state.load_force");
    check(m.base_force, "cable_state.base_force");
    if (m.header.stamp > peak_joint_rate_after) peak_kinetic_energy = std::max(peak_kinetic_energy, m.kinetic_energy);
    state = m;
    ++state_count;
  }
  void onMarkers(const visualization_msgs::MarkerArray& m) {
    for (const auto& marker : m.markers) {
      for (const auto& p : marker.points) check(p, "marker point");
      for (const auto& c : marker.colors) {
        for (double v : {c.r, c.g, c.b, c.a}) check(v, "marker colour");
      }
      check(marker.pose.position, "marker pose");
      check(marker.pose.orientation, "marker orientation");
      check(marker.scale, "marker scale");
    }
    markers = m;
    ++marker_count;
  }
  void onWrench(const geometry_msgs::WrenchStamped& m) {
    check(m.wrench.force, "rov_wrench.force");
    check(m.wrench.torque, "rov_wrench.torque");
    const double f = std::sqrt(m.wrench.force.x * m.wrench.force.x + m.wrench.force.y * m.wrench.force.y +
                               m.wrench.force.z * m.wrench.force.z);
    if (std::isfinite(f)) peak_force = std::max(peak_force, f);
    wrench = m;
    ++wrench_count;
  }
  void onTf(const tf2_msgs::TFMessage& m) {
    for (const auto& t : m.transforms) {
      check(t.transform.translation, "/tf translation");
      check(t.transform.rotation, "/tf rotation");
    }
    ++tf_count;
  }
  void onDiagnostics(const diagnostic_msgs::DiagnosticArray& m) {
    for (const auto& s : m.status) {
      if (s.name != diagnostics_name_) continue;
      for (const auto& kv : s.values) {
        if (kv.key == "winch command") continue;  // the one phrase ("pay out at 0.5 m/s", "to length 25 m")
        // Every other value is a number: it must parse whole and be finite ("nan", "inf" fail).
        char* end = nullptr;
        const double v = std::strtod(kv.value.c_str(), &end);
        if (end == kv.value.c_str() || *end != '\0') {
          if (non_finite.empty()) non_finite = "/diagnostics value '" + kv.value + "' of " + kv.key;
        } else {
          check(v, "/diagnostics value");
        }
      }
      diagnostics = s;
      ++diagnostics_count;
    }
  }

  std::string diagnostics_name_;
  std::vector<ros::Subscriber> subs_;
};

/// Spins until `done` or `seconds` of wall time pass.
inline bool waitFor(const std::function<bool()>& done, double seconds) {
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
  while (ros::ok() && ros::WallTime::now() < end) {
    ros::spinOnce();
    if (done()) return true;
    ros::WallDuration(0.005).sleep();
  }
  return done();
}

/// Spins for `seconds`, calling `each` every `period` seconds.
inline void spinFor(double seconds, const std::function<void()>& each = [] {}, double period = 0.02) {
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
  while (ros::ok() && ros::WallTime::now() < end) {
    each();
    ros::spinOnce();
    ros::WallDuration(period).sleep();
  }
}

}  // namespace cable_test
