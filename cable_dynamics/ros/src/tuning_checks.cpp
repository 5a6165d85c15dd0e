#include "cable_dynamics/ros/tuning_checks.h"

#include <cmath>
#include <sstream>

#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/params/config_section.h"
#include "cable_dynamics/ros/node_options.h"

namespace cable_dynamics {

TunableValues tunableValuesOf(const CableParams& params, double rate) {
  TunableValues v;
  v.current = params.fluid.current;
  v.drag_normal = params.fluid.drag_normal;
  v.drag_tangential = params.fluid.drag_tangential;
  v.added_mass = params.fluid.added_mass;
  v.coupling_stiffness = params.load.coupling_stiffness;
  v.coupling_damping = params.load.coupling_damping;
  v.rate = rate;
  v.winch_speed = params.winch.enabled ? params.winch.speed : 0.0;
  return v;
}

CableParams tunedParams(const YAML::Node& config_tree, const TunableValues& values, YAML::Node& tuned_tree) {
  YAML::Node tree = YAML::Clone(config_tree);
  tree["fluid"]["drag_normal"] = values.drag_normal;
  tree["fluid"]["drag_tangential"] = values.drag_tangential;
  tree["fluid"]["added_mass"] = values.added_mass;
  tree["load"]["coupling"]["stiffness"] = values.coupling_stiffness;
  tree["load"]["coupling"]["damping"] = values.coupling_damping;
  CableParams params = parseConfig(tree);  // every key checked as at start
  tuned_tree = tree;
  return params;
}

void checkTunedCurrent(const Eigen::Vector3d& current) {
  YAML::Node fluid(YAML::NodeType::Map);
  for (int i = 0; i < 3; ++i) fluid["current"].push_back(current(i));
  ConfigSection section(fluid, "fluid");
  section.numberList("current", 3, -100.0, 100.0, false, "m/s");  // fluid.current's range in the loader
}

void checkTunedRate(const YAML::Node& ros_tree, double rate) {
  YAML::Node tree = ros_tree.IsMap() ? YAML::Clone(ros_tree) : YAML::Node(YAML::NodeType::Map);
  tree["rate"] = rate;
  parseNodeOptions(tree, "");  // throws ConfigError on ros.rate (the rest passed at start)
}

bool checkTunedWinchSpeed(double speed, const WinchParams& winch, std::string& why) {
  std::ostringstream s;
  if (!winch.enabled) {
    if (speed == 0.0) return true;
    s << "winch_speed = " << speed << ": this cable has no winch (only 0)";
  } else if (!std::isfinite(speed) || std::abs(speed) > winch.max_speed) {
    s << "winch_speed = " << speed << ": expected a number in [" << -winch.max_speed << ", " << winch.max_speed
      << "] m/s (winch.max_speed)";
  } else {
    return true;
  }
  why = s.str();
  return false;
}

}  // namespace cable_dynamics
