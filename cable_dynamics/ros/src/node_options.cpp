#include "cable_dynamics/ros/node_options.h"

#include <algorithm>
#include <cmath>

#include <xmlrpcpp/XmlRpcValue.h>

#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/params/config_section.h"
#include "cable_dynamics/ros/frame_name.h"
#include "cable_dynamics/ros/input_guard.h"
#include "cable_dynamics/ros/xmlrpc_yaml.h"

namespace cable_dynamics {

int stepsPerCycleCap(const NodeOptions& options, double dt) {
  if (options.max_steps_given) return options.max_steps_per_cycle;
  const double two_periods = std::ceil(2.0 / (options.rate * dt));
  return static_cast<int>(std::clamp(two_periods, double(options.max_steps_per_cycle), 1e7));
}

NodeOptions parseNodeOptions(const YAML::Node& ros_section, const std::string& default_prefix) {
  ConfigSection ros(ros_section, "ros");
  NodeOptions o;
  o.rate = ros.number("rate", o.rate, 0.1, 10000.0, false, "Hz");
  o.world_frame = ros.text("world_frame", o.world_frame, isValidFrameName,
                           "a tf2 frame name (not empty, no leading '/', no whitespace)");
  o.frame_prefix = ros.text("frame_prefix", default_prefix, isValidFramePrefix,
                            "\"\" or a tf2 frame name prefix (no leading '/', no whitespace)");
  if (ros.has("base_position")) {
    // The same bound as every input position: beyond it derived quantities (energies) may overflow.
    const std::vector<double> b =
        ros.numberList("base_position", 3, -kMaxInputPosition, kMaxInputPosition, false, "m");
    o.base_position = Eigen::Vector3d(b[0], b[1], b[2]);
  }
  o.input_timeout = ros.number("input_timeout", o.input_timeout, 1e-3, 1e6, false, "s");
  o.max_steps_given = ros.has("max_steps_per_cycle");
  o.max_steps_per_cycle = ros.integer("max_steps_per_cycle", o.max_steps_per_cycle, 1, 10000000, false);
  o.max_lag = ros.number("max_lag", o.max_lag, 0.01, 3600.0, false, "s");
  o.tension_scale = ros.number("tension_scale", o.tension_scale, 0.0, 1e9, false, "N");
  if (ros.has("markers")) {
    ConfigSection markers = ros.sub("markers");
    o.colour_by = markers.choice("colour_by", "tension", {"tension", "utilisation"}) == "tension" ? MarkerColour::kTension
                                                                                              : MarkerColour::kUtilisation;
    markers.rejectUnknownKeys();
  }
  o.diagnostics_period = ros.number("diagnostics_period", o.diagnostics_period, 0.01, 3600.0, false, "s");
  o.min_rov_mass = ros.number("min_rov_mass", o.min_rov_mass, 0.0, 1e6, false, "kg");
  // The rviz shapes of the two bodies (scene_markers.h): drawing only.
  for (auto [key, size] : {std::pair<const char*, Eigen::Vector3d*>{"vessel_size", &o.shapes.vessel_size},
                           std::pair<const char*, Eigen::Vector3d*>{"rov_size", &o.shapes.rov_size}}) {
    if (!ros.has(key)) continue;
    const std::vector<double> v = ros.numberList(key, 3, 0.0, 1000.0, true, "m");
    *size = Eigen::Vector3d(v[0], v[1], v[2]);
  }
  ros.rejectUnknownKeys();
  return o;
}

void loadNodeParameters(const ros::NodeHandle& private_nh, CableParams& params, NodeOptions& options,
                        YAML::Node* config_tree, YAML::Node* ros_tree) {
  XmlRpc::XmlRpcValue tree;
  YAML::Node root(YAML::NodeType::Map);
  if (private_nh.getParam("", tree) && tree.getType() == XmlRpc::XmlRpcValue::TypeStruct) root = xmlRpcToYaml(tree);
  const YAML::Node& const_root = root;  // const lookup: yaml-cpp's non-const [] inserts the key
  const bool has_ros = const_root["ros"].IsDefined();
  const YAML::Node ros_section = has_ros ? YAML::Clone(const_root["ros"]) : YAML::Node();
  if (has_ros) root.remove("ros");
  if (const_root["tuning"].IsDefined()) root.remove("tuning");  // the live-tuning server's own parameters

  // Default frame prefix: the node's namespace ("/<ns>/<node>" gives "<ns>/").
  const std::string ns = private_nh.getNamespace();
  std::string parent = ns.substr(0, ns.rfind('/'));
  while (!parent.empty() && parent.front() == '/') parent.erase(0, 1);
  const std::string default_prefix = parent.empty() ? "" : parent + "/";

  params = parseConfig(root);
  options = parseNodeOptions(ros_section, default_prefix);
  if (config_tree) *config_tree = root;
  if (ros_tree) *ros_tree = ros_section;
}

}  // namespace cable_dynamics
