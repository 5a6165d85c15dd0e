#include "cable_dynamics/ros/tuning_checks.h"

#include <sstream>
#include <stdexcept>
#include <vector>

#include "cable_dynamics/params/config_loader.h"
#include "cable_dynamics/params/config_section.h"
#include "cable_dynamics/params/format_values.h"
#include "cable_dynamics/params/input_gate.h"
#include "cable_dynamics/ros/node_options.h"
#include "cable_dynamics/simulation/tunable_keys.h"

namespace cable_dynamics {

namespace {

double& current(TunableValues& v, int i) { return v.current(i); }

/// The coefficient key `key` of kTunableKeys.
const TunableKey& coefficient(const char* key) {
  for (const TunableKey& k : kTunableKeys) {
    if (std::string(k.key) == key) return k;
  }
  throw std::logic_error(std::string("tuning: ") + key + " is not among kTunableKeys");
}

}  // namespace

const std::array<TunableParameter, 11> kTunableParameters = {{
    {"current_x", kTuneCurrent, "fluid.current", [](TunableValues& v) -> double& { return current(v, 0); }},
    {"current_y", kTuneCurrent, "fluid.current", [](TunableValues& v) -> double& { return current(v, 1); }},
    {"current_z", kTuneCurrent, "fluid.current", [](TunableValues& v) -> double& { return current(v, 2); }},
    {"drag_normal", kTuneCoefficients, "fluid.drag_normal", [](TunableValues& v) -> double& { return v.drag_normal; }},
    {"drag_tangential", kTuneCoefficients, "fluid.drag_tangential",
     [](TunableValues& v) -> double& { return v.drag_tangential; }},
    {"added_mass", kTuneCoefficients, "fluid.added_mass", [](TunableValues& v) -> double& { return v.added_mass; }},
    {"coupling_stiffness", kTuneCoefficients, "load.coupling.stiffness",
     [](TunableValues& v) -> double& { return v.coupling_stiffness; }},
    {"coupling_damping", kTuneCoefficients, "load.coupling.damping",
     [](TunableValues& v) -> double& { return v.coupling_damping; }},
    {"rate", kTuneRate, "ros.rate", [](TunableValues& v) -> double& { return v.rate; }},
    {"paused", kTunePause, "", nullptr},
    {"winch_speed", kTuneWinch, "winch.max_speed", [](TunableValues& v) -> double& { return v.winch_speed; }},
}};

TunableValues tunableValuesOf(const CableParams& params, double rate) {
  TunableValues v;
  CableParams p = params;
  for (const TunableParameter& t : kTunableParameters) {
    if (t.level == kTuneCoefficients) t.at(v) = coefficient(t.key).in(p);
  }
  v.current = params.fluid.current;
  v.rate = rate;
  v.winch_speed = params.winch.enabled ? params.winch.speed : 0.0;
  return v;
}

CableParams tunedParams(const YAML::Node& config_tree, const TunableValues& values, YAML::Node& tuned_tree) {
  YAML::Node tree = YAML::Clone(config_tree);
  TunableValues v = values;
  for (const TunableParameter& t : kTunableParameters) {
    if (t.level != kTuneCoefficients) continue;
    // The key's path in the tree; yaml-cpp's nodes are handles: walk down with fresh ones.
    std::vector<YAML::Node> chain{tree};
    std::string rest = t.key;
    for (std::size_t dot; (dot = rest.find('.')) != std::string::npos; rest.erase(0, dot + 1)) {
      chain.push_back(chain.back()[rest.substr(0, dot)]);
    }
    chain.back()[rest] = t.at(v);
  }
  CableParams params = parseConfig(tree);  // every key checked as at start
  tuned_tree = tree;
  return params;
}

void adoptTree(YAML::Node& held, const YAML::Node& fresh) { held.reset(fresh); }

void checkTunedCurrent(const Eigen::Vector3d& current) { checkCurrent(current); }  // the simulator's gate

void checkTunedRate(const YAML::Node& ros_tree, double rate) {
  YAML::Node tree = ros_tree.IsMap() ? YAML::Clone(ros_tree) : YAML::Node(YAML::NodeType::Map);
  tree["rate"] = rate;
  parseNodeOptions(tree, "");  // throws ConfigError on ros.rate (the rest passed at start)
}

bool checkTunedWinchSpeed(double speed, const WinchParams& winch, std::string& why) {
  if (!winch.enabled) {
    if (speed == 0.0) return true;
    std::ostringstream s;
    s << "winch_speed = " << formatNumber(speed) << ": " << kNoWinchMessage << " (only 0)";
    why = s.str();
    return false;
  }
  try {
    checkWinchSpeed(speed, winch);  // the simulator's gate: its range and message
  } catch (const std::invalid_argument& e) {
    why = e.what();
    return false;
  }
  return true;
}

}  // namespace cable_dynamics
