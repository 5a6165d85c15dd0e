#pragma once
/// \file
/// \brief Live tuning's checks, ROS-free: each tunable value is checked with the range the config
///        loader gives its key (the same ConfigSection reads), so a value the node would refuse at start is
///        refused live too, with the same message. The dynamic_reconfigure server (live_tuning.h) and the
///        node (cable_node.cpp) apply what passes.

#include <array>
#include <string>

#include <Eigen/Core>
#include <yaml-cpp/yaml.h>

#include "cable_dynamics/params/cable_params.h"

namespace cable_dynamics {

/// The values live tuning can change, as the node has them in force.
struct TunableValues {
  Eigen::Vector3d current = Eigen::Vector3d::Zero();  ///< uniform current, world frame (z up) [m/s]
  double drag_normal = 1.2;          ///< fluid.drag_normal [-]
  double drag_tangential = 0.01;     ///< fluid.drag_tangential [-]
  double added_mass = 1.0;           ///< fluid.added_mass [-]
  double coupling_stiffness = 2.0e4; ///< load.coupling.stiffness [N/m]
  double coupling_damping = 2.0e3;   ///< load.coupling.damping [N s/m]
  double rate = 100.0;               ///< ros.rate [Hz]
  bool paused = false;
  double winch_speed = 0.0;          ///< winch command, + pays out [m/s]
};

/// Which parts a request changes (the cfg's levels, cfg/Tuning.cfg).
enum TuningLevel : unsigned {
  kTuneCurrent = 1,
  kTuneCoefficients = 2,
  kTuneRate = 4,
  kTunePause = 8,
  kTuneWinch = 16,
};

/// One parameter of live tuning, in the one list of them (kTunableParameters): the dynamic_reconfigure
/// server (live_tuning.cpp), tunableValuesOf(), tunedParams() and the node's application run over it, and
/// test_tuning checks cfg/Tuning.cfg against it (names, types, levels, and the ranges its descriptions
/// print against the ones the checks refuse with).
struct TunableParameter {
  const char* name;                 ///< the cfg's parameter name
  unsigned level;                   ///< its TuningLevel
  /// The key whose range it takes: a config key of kTunableKeys (simulation/tunable_keys.h) for a
  /// coefficient, "fluid.current", "ros.rate", "winch.max_speed"; "" for the flag `paused`.
  const char* key;
  double& (*at)(TunableValues&);    ///< its value; nullptr for the flag `paused`
};
extern const std::array<TunableParameter, 11> kTunableParameters;

/// The values of a freshly started node: its config's coefficients, `rate`, not paused, the winch's
/// configured speed (0 without one). The current is fluid.current (0 with a current profile).
TunableValues tunableValuesOf(const CableParams& params, double rate);

/// The cable's parameters with the coefficients of `values`: `config_tree` (the node's config, without
/// its `ros` section) with fluid.drag_normal, drag_tangential, added_mass, load.coupling.stiffness and
/// damping set, parsed by the config loader. Throws ConfigError naming the key, the value and the range.
/// `tuned_tree` gets the tree parsed (the next request starts from it).
CableParams tunedParams(const YAML::Node& config_tree, const TunableValues& values, YAML::Node& tuned_tree);

/// `held` becomes `fresh` (a tree the node keeps between requests), dropping the old tree's memory.
/// yaml-cpp's `held = fresh` would merge the two trees' memory pools instead, so every accepted tuning
/// kept a whole config tree alive (issue 27: about 92 kB a change, 1000 changes 95 -> 187 MB).
void adoptTree(YAML::Node& held, const YAML::Node& fresh);

/// The current's three components in fluid.current's range, [-100, 100] m/s each, finite (ConfigError
/// on `fluid.current` otherwise).
void checkTunedCurrent(const Eigen::Vector3d& current);

/// ros.rate in its range, [0.1, 10000] Hz (ConfigError on `ros.rate` otherwise): `ros_tree` is the
/// node's `ros` section, checked whole with the rate replaced, as at start.
void checkTunedRate(const YAML::Node& ros_tree, double rate);

/// A winch command: without a winch only 0 passes; with one, finite and |speed| <= winch.max_speed.
/// Returns false with the reason in `why`.
bool checkTunedWinchSpeed(double speed, const WinchParams& winch, std::string& why);

}  // namespace cable_dynamics
