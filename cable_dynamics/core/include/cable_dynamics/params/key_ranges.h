#pragma once
/// \file
/// \brief Each config key's allowed range, written once. The config loader reads a key with its range
///        (ConfigSection), and the gate checks a CableParams against the same ranges
///        (checkConfigRanges, params/input_gate.h), so parameters filled in by hand in C++ are refused
///        with the key, the value and the range a config would be refused with.

#include <cmath>
#include <limits>
#include <string>

namespace cable_dynamics {

/// An allowed range of a real number: [lo, hi], or (lo, hi] when lo_open; never NaN or infinite.
struct NumberRange {
  double lo;
  double hi;
  bool lo_open;
  const char* unit;  ///< for messages; "" for a dimensionless value

  bool allows(double v) const { return std::isfinite(v) && (lo_open ? v > lo : v >= lo) && v <= hi; }
  /// As refusals print it: "a finite number in (0, 100000] [m]".
  std::string text() const;
};

/// An allowed range of an integer, [lo, hi].
struct IntegerRange {
  int lo;
  int hi;

  bool allows(long v) const { return v >= lo && v <= hi; }
  /// "an integer in [1, 10000]".
  std::string text() const;
};

/// Largest |component| of the current, as fluid.current in a config, setCurrent and the node's current
/// topic [m/s].
constexpr double kMaxCurrentSpeed = 100.0;

namespace ranges {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = M_PI;

// cable
constexpr IntegerRange kLinks{1, 10000};  ///< cable.links, and links with a winch's drum slots in all
constexpr NumberRange kLength{0.0, 1e5, true, "m"};  ///< cable.length, link_lengths[i], sections[i].length
constexpr NumberRange kDiameter{0.0, 10.0, true, "m"};
/// cable.mass_per_length: also what a material density within its range gives over a diameter within its range.
constexpr NumberRange kMassPerLength{0.0, 1e7, true, "kg/m"};
constexpr NumberRange kMaterialDensity{0.0, 1e5, true, "kg/m^3"};
constexpr NumberRange kAxialStiffness{0.0, 1e13, false, "N"};
constexpr NumberRange kAxialDamping{0.0, 1e13, false, "N s"};
constexpr NumberRange kMaxTension{0.0, 1e12, true, "N"};
constexpr NumberRange kBendRadius{0.0, 1e5, true, "m"};
constexpr NumberRange kSeabedClearance{0.0, 1e5, false, "m"};
constexpr NumberRange kJointStiffness{0.0, kInf, false, "N m/rad"};
constexpr NumberRange kRigidity{0.0, kInf, false, "N m^2"};
constexpr NumberRange kJointDamping{0.0, kInf, false, "N m s/rad"};
/// A Morison drag or added-mass coefficient (fluid.*, sections[i].*).
constexpr NumberRange kCoefficient{0.0, 100.0, false, ""};

// a prescribed motion (load.motion, base.motion)
constexpr NumberRange kMotionOffset{-1e5, 1e5, false, "m"};
constexpr NumberRange kMotionAmplitude{-1e4, 1e4, false, "m"};
constexpr NumberRange kMotionPeriod{0.0, 1e6, true, "s"};
constexpr NumberRange kPhase{-2.0 * kPi, 2.0 * kPi, false, "rad"};  ///< phase, attitude_phase
constexpr NumberRange kMotionVelocity{-100.0, 100.0, false, "m/s"};
constexpr NumberRange kAttitudeAngle{-kPi, kPi, false, "rad"};  ///< attitude_amplitude, body initial_attitude

// the load, an attachment point
constexpr NumberRange kMass{0.0, 1e7, false, "kg"};
constexpr NumberRange kVolume{0.0, 1e4, false, "m^3"};
constexpr NumberRange kDragArea{0.0, 1e4, false, "m^2"};
constexpr NumberRange kAddedMass{0.0, 1e7, false, "kg"};
constexpr NumberRange kCouplingStiffness{0.0, 1e9, true, "N/m"};
constexpr NumberRange kCouplingDamping{0.0, 1e9, false, "N s/m"};
constexpr NumberRange kCouplingIntegralTime{0.0, 1e4, false, "s"};  ///< 0 = no integral action
constexpr NumberRange kBodyPoint{-1e3, 1e3, false, "m"};  ///< load.attachment, base.hang_off
constexpr NumberRange kDirection{-1e3, 1e3, false, ""};   ///< load.direction, base.direction (normalized)

// load.body (the ROV)
constexpr NumberRange kInertia{-1e9, 1e9, false, "kg m^2"};
constexpr NumberRange kBodyAddedMass{-1e9, 1e9, false, "kg, kg m, kg m^2"};
constexpr NumberRange kLinearDamping{0.0, 1e9, false, "N s/m, N m s/rad"};
constexpr NumberRange kQuadraticDamping{0.0, 1e9, false, "N s^2/m^2, N m s^2/rad^2"};
constexpr NumberRange kBodyCentre{-100.0, 100.0, false, "m"};
constexpr NumberRange kPositionGain{0.0, 1e9, false, "N/m"};
constexpr NumberRange kVelocityGain{0.0, 1e9, false, "N s/m"};
constexpr NumberRange kIntegralGain{0.0, 1e9, false, "N/(m s)"};
constexpr NumberRange kAttitudeGain{0.0, 1e9, false, "N m/rad"};
constexpr NumberRange kRateGain{0.0, 1e9, false, "N m s/rad"};
constexpr NumberRange kMaxForce{0.0, 1e300, false, "N"};
constexpr NumberRange kMaxTorque{0.0, 1e300, false, "N m"};

// fluid
constexpr NumberRange kFluidDensity{0.0, 2.0e4, false, "kg/m^3"};
constexpr NumberRange kCurrent{-kMaxCurrentSpeed, kMaxCurrentSpeed, false, "m/s"};
constexpr IntegerRange kDragPoints{1, 8};
constexpr NumberRange kProfileRow{-1e5, 1e5, false, "m, m/s"};  ///< fluid.current_profile[i]: depth, current
constexpr NumberRange kGravity{0.0, 100.0, false, "m/s^2"};

// seabed
constexpr NumberRange kSeabedDepth{0.0, 1e5, true, "m"};
constexpr NumberRange kGridOrigin{-1e7, 1e7, false, "m"};
constexpr NumberRange kGridSpacing{0.0, 1e6, true, "m"};
constexpr NumberRange kGridDepth{-1e5, 1e5, false, "m"};
constexpr NumberRange kPenetration{0.0, 1e3, true, "m"};
constexpr NumberRange kSeabedStiffness{0.0, 1e12, false, "N/m^2 (0: from the penetration)"};
constexpr NumberRange kDampingRatio{0.0, 10.0, false, ""};
constexpr NumberRange kFriction{0.0, 10.0, false, ""};
constexpr NumberRange kFrictionVelocity{0.0, 10.0, true, "m/s"};
constexpr NumberRange kFrictionBreakout{0.0, 1.0, false, "m"};
constexpr IntegerRange kContactPoints{1, 16};

// initial
constexpr NumberRange kInitialAngle{-kPi, kPi, false, "rad"};  ///< initial.elevation, initial.azimuth
constexpr NumberRange kInitialTorsion{-1e3, 1e3, false, "rad"};

// simulation
constexpr NumberRange kDt{0.0, 0.1, true, "s"};
constexpr NumberRange kRhoInfinity{0.0, 1.0, false, ""};
constexpr NumberRange kDuration{0.0, 1e7, true, "s"};

// winch (the ranges of its lengths and speeds depend on the cable's: the functions below)
constexpr NumberRange kWinchMaxSpeed{0.0, 100.0, true, "m/s"};
constexpr NumberRange kWinchMaxAcceleration{0.0, 1e3, true, "m/s^2"};
constexpr NumberRange kScheduleTime{0.0, 1e7, false, "s"};
/// winch.max_length: at least the configured deployment `deployed` [m].
constexpr NumberRange winchMaxLength(double deployed) { return {deployed, 1e5, false, "m"}; }
/// winch.min_length: from one link of the base link's length `link` up to the deployment [m].
constexpr NumberRange winchMinLength(double link, double deployed) { return {link, deployed, false, "m"}; }
/// winch.speed, a schedule's speed: within +-winch.max_speed [m/s].
constexpr NumberRange winchSpeed(double max_speed) { return {-max_speed, max_speed, false, "m/s"}; }
/// A schedule's length: within [winch.min_length, winch.max_length] [m].
constexpr NumberRange winchLength(double min_length, double max_length) { return {min_length, max_length, false, "m"}; }

/// attachments[i].arc_length: along the configured cable of length `total` [m].
constexpr NumberRange arcLength(double total) { return {0.0, total, false, "m"}; }

}  // namespace ranges
}  // namespace cable_dynamics
