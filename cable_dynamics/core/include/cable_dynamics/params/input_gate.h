#pragma once
/// \file
/// \brief The one gate for the simulator's inputs: the limits on live inputs (written here once), the
///        rules between config keys, the paper model's singular springs, and the checks of the values the
///        simulator's setters take. Each refusal throws std::invalid_argument (ConfigError for a config
///        key) whose message names the key, the value and the allowed range. The config loader calls checkConfigRules(); the
///        simulator's constructor, retune() and its setters call the rest (CableSimulator::checkInputs adds
///        RK4's stable step, simulation/stable_step.h), so cable_sim, the node, the nodelet, live tuning and
///        Python refuse the same inputs with the same message. The node's input guard
///        (ros/input_guard.h) judges messages with the predicates below before they reach a setter.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "cable_dynamics/params/cable_params.h"
#include "cable_dynamics/params/config_section.h"
#include "cable_dynamics/params/key_ranges.h"

namespace cable_dynamics {

// Limits on live inputs, world axes (z up) from the base's rest position.

/// Largest |coordinate| of a target position (the ROV's attachment point, the vessel's hang-off point)
/// [m]: beyond it derived quantities (energies, forces) can overflow a double.
constexpr double kMaxInputPosition = 1e6;
/// Fastest target: a pose stream implying a faster ROV or base is a jump [m/s].
constexpr double kMaxInputSpeed = 20.0;
/// Largest thrust force and torque an ROV body takes (each component) [N], [N m]: beyond any thruster.
constexpr double kMaxThrust = 1e7;
// kMaxCurrentSpeed, the current's limit, is fluid.current's range (params/key_ranges.h).

/// The text of a winch command on a cable without a winch.
extern const char* const kNoWinchMessage;

/// Every value of `p` within its key's range (params/key_ranges.h, the ranges the config loader reads
/// with), and the shapes a config gives: one link length and one initial angle of each kind per link,
/// section lengths adding up to the cable's, a winch's drum slots as the loader counts them, unit
/// directions, a profile's depths increasing. For parameters filled in by hand in C++; a config's pass
/// again. `p` may be the configured cable or the model's copy with a winch's drum slots built. Throws
/// ConfigError naming the key (`cable.sections[2].diameter`, `load.motion.offset[1]`), the value and the
/// range, as the loader does (range_gate.cpp).
void checkConfigRanges(const CableParams& p);

/// The rules between config keys that a parsed config obeys (one stiffness law or the other, what a
/// winch, a clamped tip and the paper model allow), after checkConfigRanges(). Throws ConfigError on the
/// first broken one.
void checkConfigRules(const CableParams& p);

/// What the simulator adds: the paper's azimuth and torsion springs and dampers are singular at the
/// vertical, and its elevation damper needs RK4 (semi-implicit) or the bending model (implicit).
/// Throws ConfigError naming the key.
void checkSimulatorRules(const CableParams& p);

// Predicates (the node's guard judges messages with them) and the checks that throw (the setters).

/// Every component finite and within +-kMaxInputPosition.
bool positionAllowed(const Eigen::Vector3d& position);
/// Finite, |velocity| <= kMaxInputSpeed (up to the rounding of a tracker's quotient).
bool velocityAllowed(const Eigen::Vector3d& velocity);
/// Every component finite and within +-kMaxCurrentSpeed.
bool currentAllowed(const Eigen::Vector3d& current);
/// Finite and |speed| <= max_speed.
bool winchSpeedAllowed(double speed, double max_speed);

/// `key` = position [m] (`key` names the input, e.g. "load target position").
void checkPosition(const char* key, const Eigen::Vector3d& position);
/// `key` = velocity [m/s].
void checkVelocity(const char* key, const Eigen::Vector3d& velocity);
/// A finite quaternion of unit length (within 1e-6).
void checkAttitude(const char* key, const Eigen::Quaterniond& attitude);
/// A uniform current in world axes [m/s]: fluid.current's range, each component named as the loader
/// names it (fluid.current[i]).
void checkCurrent(const Eigen::Vector3d& current);
/// Every component of a thrust (force [N] or torque [N m]) finite and within +-kMaxThrust.
bool thrustAllowed(const Eigen::Vector3d& thrust);
/// `key` = thrust: thrustAllowed.
void checkThrust(const char* key, const Eigen::Vector3d& thrust);
/// A winch speed command [m/s] within +-winch.max_speed.
void checkWinchSpeed(double speed, const WinchParams& winch);
/// A winch length target [m] within [winch.min_length, winch.max_length].
void checkWinchLength(double length, const WinchParams& winch);

}  // namespace cable_dynamics
