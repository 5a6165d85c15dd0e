#include "cable_dynamics/ros/node_options.h"

#include <algorithm>
#include <cmath>

#include <xmlrpcpp/XmlRpcValue.h>
#include <yaml-cpp/yaml.h>

#include "cable_dynamics/params/config_loader.h"

namespace cable_dynamics {
namespace {

/// The parameter server's tree as YAML, so the config loader checks it exactly as it checks a file.
YAML::Node toYaml(XmlRpc::XmlRpcValue& v) {
  switch (v.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean:
      return YAML::Node(static_cast<bool>(v));
    case XmlRpc::XmlRpcValue::TypeInt:
      return YAML::Node(static_cast<int>(v));
    case XmlRpc::XmlRpcValue::TypeDouble: {
      const double d = static_cast<double>(v);
      // yaml-cpp writes non-finite numbers as .nan/.inf, which the loader then rejects by name.
      return YAML::Node(d);
    }
    case XmlRpc::XmlRpcValue::TypeString:
      return YAML::Node(static_cast<std::string>(v));
    case XmlRpc::XmlRpcValue::TypeArray: {
      YAML::Node seq(YAML::NodeType::Sequence);
      for (int i = 0; i < v.size(); ++i) seq.push_back(toYaml(v[i]));
      return seq;
    }
    case XmlRpc::XmlRpcValue::TypeStruct: {
      YAML::Node map(YAML::NodeType::Map);
      for (auto& kv : v) map[kv.first] = toYaml(kv.second);
      return map;
    }
    default:
      return YAML::Node(v.toXml());
  }
}

double number(const YAML::Node& ros, const std::string& key, double fallback, double lo, double hi) {
  if (!ros[key]) return fallback;
  double value = NAN;
  try {
    value = ros[key].as<double>();
  } catch (const YAML::Exception&) {
  }
  if (!std::isfinite(value) || value < lo || value > hi) {
    throw ConfigError("ros." + key, YAML::Dump(ros[key]),
                      "a number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  }
  return value;
}

std::string text(const YAML::Node& ros, const std::string& key, const std::string& fallback) {
  if (!ros[key]) return fallback;
  if (!ros[key].IsScalar()) throw ConfigError("ros." + key, YAML::Dump(ros[key]), "a frame name");
  return ros[key].Scalar();
}

}  // namespace

void loadNodeParameters(const ros::NodeHandle& private_nh, CableParams& params, NodeOptions& options) {
  XmlRpc::XmlRpcValue tree;
  YAML::Node root(YAML::NodeType::Map);
  if (private_nh.getParam("", tree) && tree.getType() == XmlRpc::XmlRpcValue::TypeStruct) root = toYaml(tree);
  const YAML::Node& const_root = root;  // const lookups: yaml-cpp's non-const [] inserts the key
  const bool has_ros = static_cast<bool>(const_root["ros"]);
  YAML::Node ros = has_ros ? YAML::Clone(const_root["ros"]) : YAML::Node(YAML::NodeType::Map);
  if (has_ros) root.remove("ros");
  params = parseConfig(root);

  std::string ns = private_nh.getNamespace();  // "/<ns>/<node>"
  const std::size_t last = ns.rfind('/');
  std::string parent = last == std::string::npos ? "" : ns.substr(0, last);
  while (!parent.empty() && parent.front() == '/') parent.erase(0, 1);
  NodeOptions o;
  o.frame_prefix = parent.empty() ? "" : parent + "/";
  if (has_ros) {
    if (!ros.IsMap()) throw ConfigError("ros", YAML::Dump(ros), "a mapping of keys");
    const std::vector<std::string> known = {"rate", "world_frame", "frame_prefix", "base_position", "input_timeout",
                                            "max_steps_per_cycle", "tension_scale", "diagnostics_period"};
    for (const auto& kv : ros) {
      const std::string key = kv.first.as<std::string>();
      if (std::find(known.begin(), known.end(), key) == known.end()) {
        throw ConfigError("ros." + key, YAML::Dump(kv.second), "no such key; known: rate world_frame frame_prefix "
                                                                "base_position input_timeout max_steps_per_cycle "
                                                                "tension_scale diagnostics_period");
      }
    }
    o.rate = number(ros, "rate", o.rate, 0.1, 10000.0);
    o.world_frame = text(ros, "world_frame", o.world_frame);
    o.frame_prefix = text(ros, "frame_prefix", o.frame_prefix);
    o.input_timeout = number(ros, "input_timeout", o.input_timeout, 1e-3, 1e6);
    o.max_steps_per_cycle = static_cast<int>(number(ros, "max_steps_per_cycle", o.max_steps_per_cycle, 1, 1e7));
    o.tension_scale = number(ros, "tension_scale", o.tension_scale, 0.0, 1e9);
    o.diagnostics_period = number(ros, "diagnostics_period", o.diagnostics_period, 0.01, 3600.0);
    if (ros["base_position"]) {
      const YAML::Node b = ros["base_position"];
      if (!b.IsSequence() || b.size() != 3) throw ConfigError("ros.base_position", YAML::Dump(b), "a list of 3 numbers [m]");
      for (int i = 0; i < 3; ++i) {
        double v = NAN;
        try {
          v = b[i].as<double>();
        } catch (const YAML::Exception&) {
        }
        if (!std::isfinite(v)) throw ConfigError("ros.base_position[" + std::to_string(i) + "]", YAML::Dump(b[i]), "a finite number [m]");
        o.base_position(i) = v;
      }
    }
    if (o.world_frame.empty()) throw ConfigError("ros.world_frame", "\"\"", "a non-empty frame name");
  }
  if (o.max_steps_per_cycle < 1) throw ConfigError("ros.max_steps_per_cycle", "0", "an integer >= 1");
  options = o;
}

}  // namespace cable_dynamics
