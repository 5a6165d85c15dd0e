#pragma once
/// \file
/// \brief What holds the cable's ends at each instant: the base's prescribed or external motion and the
///        load's anchor or ROV target. Inputs in world axes (REP-103, z up) with the origin at the base's
///        rest position; the dynamics get them in the paper frame (EndInputs).

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "cable_dynamics/dynamics/state_layout.h"
#include "cable_dynamics/params/cable_params.h"
#include "cable_dynamics/simulation/winch.h"

namespace cable_dynamics {

/// Position, velocity and acceleration at time t [s] of the point `offset` (body frame [m]) of a body
/// moving by `motion`, relative to that point's rest position, in the paper frame [m, m/s, m/s^2]
/// (body_motion.h).
void motionAt(const MotionParams& motion, const Eigen::Vector3d& offset, double t, Eigen::Vector3d& position,
              Eigen::Vector3d& velocity, Eigen::Vector3d& acceleration);

/// The ends' inputs over time: the configured motions until an external target replaces them.
class EndConditions {
 public:
  EndConditions(const BaseParams& base, const LoadParams& load, const WinchParams& winch);

  /// The inputs at time t [s] (paper frame).
  EndInputs at(double t) const;

  /// Back to the configured motions (external targets dropped).
  void reset();

  /// The base clamp at rest (paper frame: unit axis, twist sigma [rad]; LinkProperties): with a vessel
  /// attitude the clamp turns with the vessel (EndInputs::clamp_*).
  void setRestClamp(const Eigen::Vector3d& axis, double twist);

  /// The winch at the base (when configured), which sets the deployed length.
  bool hasWinch() const { return has_winch_; }
  Winch& winch() { return winch_; }
  const Winch& winch() const { return winch_; }
  /// The deployed cable beyond the winch's own link [m]: the winch's link is the rest of the deployed length.
  void setOutboardLength(double length) { outboard_length_ = length; }
  double outboardLength() const { return outboard_length_; }
  /// The tip's start position (paper frame) [m], which the load's configured motion is relative to.
  void setInitialTip(const Eigen::Vector3d& initial_tip) { initial_tip_ = initial_tip; }
  /// External load target (world axes) [m], [m/s]: the attachment point of the ROV at simulated time
  /// `time` [s], whose attitude is `attitude` (world from ROV); replaces the configured motion until
  /// reset(). Between poses the point moves on with `velocity` (a first-order hold, at most
  /// kTargetExtrapolation either side of `time`): a held point with a moving velocity would pull the cable
  /// one exchange behind the ROV, which destabilises a light ROV that exchanges poses and wrenches with
  /// this simulator (docs/ROV_COUPLING.md).
  void setLoadTarget(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity,
                     const Eigen::Quaterniond& attitude, double time);
  /// How far in time a pose is carried on by its velocity [s]; beyond it the point stops (a stream that
  /// stopped must not drag the cable away).
  static constexpr double kTargetExtrapolation = 0.25;
  /// External base position and velocity (world axes) [m], [m/s]: the hang-off point of the vessel,
  /// whose attitude is `attitude`; replaces the configured motion.
  void setBaseTarget(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity,
                     const Eigen::Quaterniond& attitude = Eigen::Quaterniond::Identity());
  /// The ROV body's thrust (load.mode body): force and moment at its origin, body frame [N, N m], held
  /// until the next call (the simulator sets it each step: commanded thrust plus station keeping).
  void setBodyThrust(const Eigen::Matrix<double, 6, 1>& thrust) { body_thrust_ = thrust; }
  /// An exact anchor held by the implicit steps' internal spring (ChainModel::holdStiffness): the spring's
  /// rest point lies this far beyond the anchor (paper frame [m]), so that it carries the anchor's force
  /// with the tip on the anchor. The simulator sets it from the statics' reaction. Zero otherwise, and
  /// after reset().
  void setHoldOffset(const Eigen::Vector3d& offset) { hold_offset_ = offset; }
  const Eigen::Vector3d& holdOffset() const { return hold_offset_; }
  /// A bumpless change of the coupling's stiffness (CableSimulator::retune): from time t [s] the coupling's
  /// rest point lies `shift` (paper frame [m]) from the target, so that the new spring carries the force
  /// the old one did, and the shift bleeds off as s(t') = shift (1 + a) e^-a, a = (t' - t) / kCouplingShiftBleed,
  /// a critically damped profile that starts with zero rate (the damper sees the rest point's rate, so that
  /// a tip following it feels no drag from it, and that rate starts at zero, so its force is continuous too).
  /// The tip then moves to the new spring's extension slowly against the coupling's modes: a new stiffness
  /// applied in one step changed the force at the extension it held by (k_new / k_old - 1) of it, 38 % when
  /// the exchange's sizer softened 2980 to 1832 N/m, and rang the tip's mode on the coupling for seconds.
  /// Zero after reset().
  void shiftCouplingRest(const Eigen::Vector3d& shift, double t) {
    coupling_shift_ = shift;
    coupling_shift_time_ = t;
  }
  /// The shift at time t [m] and its rate [m/s].
  void couplingRestShift(double t, Eigen::Vector3d& shift, Eigen::Vector3d& rate) const;
  /// The coupling's integral action (load.coupling.integral_time T_i > 0): after each step of h [s] the rest
  /// point moves by -h / T_i times the tip's offset from the target (`tip_from_target`, paper frame [m]), and
  /// holds between steps (it is not bled off then). At rest the tip is on the target and the spring carries
  /// the force with its rest point F / k beyond it: the ROV feels the force the cable has at its own point,
  /// not at a point F / k away (near the tether's reach that offset changed the pull by 8 %), while within
  /// T_i the coupling is the soft spring the exchange needs.
  bool couplingIntegral() const { return load_.coupling_integral_time > 0.0; }
  void integrateCouplingRest(const Eigen::Vector3d& tip_from_target, double h) {
    coupling_shift_ -= (h / load_.coupling_integral_time) * tip_from_target;
  }
  /// The bleed's time constant [s]: slow against the coupled modes (a 5 kg ROV on 1.8 kN/m: 0.33 s) and the
  /// cable's own swing (a 12 m tether in a current: about 7 s), so that the tip follows it quasi-statically
  /// (test_tuning: at 2 s the force overshot the new equilibrium's by 0.28 %, at 4 s by 0.007 %); 0.5 % of
  /// the shift is left after 30 s, 5e-6 after 60 s.
  static constexpr double kCouplingShiftBleed = 4.0;
  /// The vessel's and the ROV's attitude at time t (world from body): external, or the configured motion's.
  Eigen::Quaterniond baseAttitude(double t) const;
  Eigen::Quaterniond loadAttitude(double t) const;

 private:
  BaseParams base_;
  LoadParams load_;
  Eigen::Vector3d initial_tip_ = Eigen::Vector3d::Zero();  ///< paper frame [m]
  bool external_load_ = false, external_base_ = false;
  bool has_winch_ = false;
  Eigen::Matrix3d rest_clamp_ = Eigen::Matrix3d::Identity();  ///< the clamp's frame at rest, paper frame
  double rest_clamp_twist_ = 0.0;                             ///< [rad]
  double external_clamp_twist_ = 0.0;  ///< the clamp's twist under the last external attitude, unwrapped [rad]
  Winch winch_;
  double outboard_length_ = 0.0;  ///< [m]
  // External targets, converted to the paper frame once [m], [m/s].
  Eigen::Vector3d load_position_ = Eigen::Vector3d::Zero(), load_velocity_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d base_position_ = Eigen::Vector3d::Zero(), base_velocity_ = Eigen::Vector3d::Zero();
  Eigen::Quaterniond load_attitude_ = Eigen::Quaterniond::Identity(), base_attitude_ = Eigen::Quaterniond::Identity();
  double load_time_ = 0.0;  ///< simulated time of the external load target [s]
  Eigen::Matrix<double, 6, 1> body_thrust_ = Eigen::Matrix<double, 6, 1>::Zero();  ///< [N, N m], body frame
  Eigen::Vector3d hold_offset_ = Eigen::Vector3d::Zero();  ///< paper frame [m]
  Eigen::Vector3d coupling_shift_ = Eigen::Vector3d::Zero();  ///< at coupling_shift_time_, paper frame [m]
  double coupling_shift_time_ = 0.0;                          ///< [s]
};

}  // namespace cable_dynamics
