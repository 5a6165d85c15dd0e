#include "cable_dynamics/tools/bag_recorder.h"

#include <algorithm>
#include <stdexcept>

#include <boost/make_shared.hpp>
#include <ros/message_traits.h>
#include <rosbag/bag.h>
#include <rosbag/exceptions.h>
#include <std_msgs/String.h>
#include <tf2_msgs/TFMessage.h>

#include "cable_dynamics/ros/finite_messages.h"
#include "cable_dynamics/ros/message_builders.h"
#include "cable_dynamics/ros/output_source.h"
#include "cable_dynamics/urdf/cable_urdf.h"

namespace cable_dynamics {

struct BagRecorder::Impl {
  BagLayout layout;
  CableParams params;
  CableFrameNames names;
  rosbag::Bag bag;
  OutputSource source;
  CableOutputs outputs;
  NodeStatus status;  ///< sim_time only: the node's wall-clock figures have no meaning offline
  tf2_msgs::TFMessage tf;
  double max_tension_seen = 0.0;
  ros::Time last_stamp;
  bool open = false;

  std::string topic(const std::string& name) const { return "/" + layout.ns + "/" + name; }
};

BagRecorder::BagRecorder(const std::string& path, const CableParams& params, const BagLayout& layout)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.layout = layout;
  m.params = params;
  m.names.prefix = layout.ns + "/";
  try {
    m.bag.open(path, rosbag::bagmode::Write);
  } catch (const rosbag::BagException& e) {
    throw std::runtime_error("cannot write " + path + ": " + e.what());
  }
  m.open = true;
  prepareOutputs(params, m.names, layout.world_frame, m.outputs);
  // The node's robot_description parameter, as a latched topic (written once, at the first instant).
  std_msgs::String description;
  description.data = cableUrdf(deriveLinkProperties(params), m.names);
  auto header = boost::make_shared<ros::M_string>();
  (*header)["callerid"] = "/cable_sim";
  (*header)["topic"] = m.topic("robot_description");
  (*header)["type"] = ros::message_traits::datatype(description);
  (*header)["md5sum"] = ros::message_traits::md5sum(description);
  (*header)["message_definition"] = ros::message_traits::definition(description);
  (*header)["latching"] = "1";
  m.bag.write(m.topic("robot_description"), stampOf(0.0, layout), description, header);
}

BagRecorder::~BagRecorder() {
  std::string ignored;
  close(ignored);
}

bool BagRecorder::record(CableSimulator& sim, std::string& error) {
  Impl& m = *impl_;
  if (!m.open) {
    error = "the bag is closed";
    return false;
  }
  // readOutputs fills the source in place: the spring forces sized once, for every slot (as the node does).
  if (m.source.spring_force.size() != 3 * sim.links()) m.source.spring_force = Eigen::VectorXd::Zero(3 * sim.links());
  if (!readOutputs(sim, m.source)) {
    error = "non-finite state (nothing of it written)";
    return false;
  }
  const ros::Time stamp = stampOf(sim.time(), m.layout);
  if (stamp <= m.last_stamp) {
    error = "simulated time did not advance";
    return false;
  }
  m.status.sim_time = sim.time();
  m.status.winch = winchStatus(m.source);
  m.max_tension_seen = std::max(m.max_tension_seen, m.source.snapshot.chain.tension.maxCoeff());
  const double scale = m.layout.tension_scale > 0.0 ? m.layout.tension_scale : m.max_tension_seen;
  const Eigen::Vector3d base_position = Eigen::Vector3d::Zero();  // the node's ros.base_position default
  CableOutputs& out = m.outputs;
  shapeOutputs(m.source.snapshot.first_link, out);
  fillJointState(m.source, stamp, out.joints);
  fillTransforms(m.source, base_position, stamp, out.transforms);
  fillMarkers(m.source, m.params.totalLength(), scale, stamp, out.markers);
  fillCableState(m.source, m.status, stamp, out.state);
  fillWrenches(m.source, base_position, stamp, out);
  if (!allFinite(out)) {
    error = "non-finite output (nothing of it written)";
    return false;
  }
  m.tf.transforms = out.transforms;
  m.tf.transforms.insert(m.tf.transforms.end(), out.body_transforms.begin(), out.body_transforms.end());
  try {
    m.bag.write(m.topic("joint_states"), stamp, out.joints);
    m.bag.write("/tf", stamp, m.tf);
    m.bag.write(m.topic("cable_markers"), stamp, out.markers);
    m.bag.write(m.topic("cable_state"), stamp, out.state);
    m.bag.write(m.topic("rov_wrench"), stamp, out.wrench);
    m.bag.write(m.topic("rov_wrench_world"), stamp, out.wrench_world);
    m.bag.write(m.topic("base_wrench"), stamp, out.base_wrench);
    m.bag.write(m.topic("base_wrench_world"), stamp, out.base_wrench_world);
  } catch (const rosbag::BagException& e) {
    error = e.what();
    return false;
  }
  m.last_stamp = stamp;
  return true;
}

bool BagRecorder::close(std::string& error) {
  Impl& m = *impl_;
  if (!m.open) return true;
  m.open = false;
  try {
    m.bag.close();
  } catch (const rosbag::BagException& e) {
    error = e.what();
    return false;
  }
  return true;
}

SampleRecorderFactory bagRecorderFactory() {
  return [](const std::string& path, const CableParams& params) -> std::unique_ptr<SampleRecorder> {
    return std::make_unique<BagRecorder>(path, params);
  };
}

}  // namespace cable_dynamics
