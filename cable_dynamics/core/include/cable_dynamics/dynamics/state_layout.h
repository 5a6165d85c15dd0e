#pragma once
/// \file
/// \brief The flat state vector x the integrators step, and the end inputs of one evaluation.

#include <Eigen/Core>

namespace cable_dynamics {

/// Layout of the flat state vector x (size 7n + 2, and 7 more with an ROV body): per link its unit axis u_k, its total twist about
/// the vertical sigma_k = psi_k + phi_k and its angular velocity omega_k (paper frame), then two energy
/// accumulators.
struct StateLayout {
  static constexpr int kPerLink = 7;  ///< u (3), sigma (1), omega (3)
  static int axis(int k) { return kPerLink * k; }
  static int twist(int k) { return kPerLink * k + 3; }
  static int omega(int k) { return kPerLink * k + 4; }
  static int dissipated(int n) { return kPerLink * n; }  ///< energy taken out by drag, added mass, dampers [J]
  static int workInput(int n) { return kPerLink * n + 1; }  ///< work done by the moving ends [J]
  /// With an ROV body (load.mode body) x ends with its attitude (paper frame from body frame, a unit
  /// quaternion w, x, y, z) and its angular velocity (body frame) [rad/s] (dynamics/rov_body.h).
  static constexpr int kBody = 7;
  static int bodyAttitude(int n) { return kPerLink * n + 2; }
  static int bodyOmega(int n) { return kPerLink * n + 6; }
  /// With axial elasticity (cable.axial_stiffness > 0) x ends with each link's stretch s_k [m] (n), then
  /// its rate [m/s] (n), after the body's entries when there is a body (docs/MODEL.md section 12).
  static int stretch(int n, bool body, int k) { return kPerLink * n + 2 + (body ? kBody : 0) + k; }
  static int stretchRate(int n, bool body, int k) { return stretch(n, body, n + k); }
  static int size(int n, bool body = false, bool axial = false) {
    return kPerLink * n + 2 + (body ? kBody : 0) + (axial ? 2 * n : 0);
  }
  /// The part of a state of `size` entries that moves when slots [0, first) are on a winch's drum:
  /// everything from link `first` on, the accumulators and a body included (the tail of x).
  static int moving(Eigen::Index size, int first) { return static_cast<int>(size) - kPerLink * first; }
};

/// What drives the ends during one evaluation (paper frame, z down, origin at the base's rest position).
struct EndInputs {
  double time = 0.0;  ///< [s] the simulator's time these inputs are at (the winch's joint holds read it)
  Eigen::Vector3d base_position = Eigen::Vector3d::Zero();      ///< [m]
  Eigen::Vector3d base_velocity = Eigen::Vector3d::Zero();      ///< [m/s]
  Eigen::Vector3d base_acceleration = Eigen::Vector3d::Zero();  ///< [m/s^2]
  bool load_coupled = false;                                    ///< PD coupling of the tip to a target
  Eigen::Vector3d target_position = Eigen::Vector3d::Zero();    ///< [m]
  Eigen::Vector3d target_velocity = Eigen::Vector3d::Zero();    ///< [m/s]
  Eigen::Vector3d target_acceleration = Eigen::Vector3d::Zero();  ///< [m/s^2] (an exact anchor's hold reads it)
  /// The coupling's rest point lies this far from the target [m] and moves from it at this rate [m/s]
  /// (paper frame): a retuned stiffness keeps the spring's force continuous through this shift, which then
  /// bleeds off (EndConditions::shiftCouplingRest), or the coupling's integral action holds the tension in it
  /// (EndConditions::integrateCouplingRest). Zero otherwise. The published attachment point is the target.
  Eigen::Vector3d coupling_rest_shift = Eigen::Vector3d::Zero();
  Eigen::Vector3d coupling_rest_shift_rate = Eigen::Vector3d::Zero();
  /// The base's clamp turns with the vessel (bending model): its axis (unit), its twist sigma [rad] and
  /// its angular velocity [rad/s]. Otherwise the clamp is LinkProperties::clamp_axis and clamp_twist, at rest.
  bool clamp_moves = false;
  Eigen::Vector3d clamp_axis = Eigen::Vector3d::UnitZ();
  double clamp_twist = 0.0;
  Eigen::Vector3d clamp_omega = Eigen::Vector3d::Zero();
  /// A clamped tip turned with the ROV (attached, load.fixity clamped): the clamp's axis (unit) and its
  /// angular velocity [rad/s]. Otherwise LinkProperties::tip_clamp_axis, at rest.
  bool tip_clamp_moves = false;
  Eigen::Vector3d tip_clamp_axis = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d tip_clamp_omega = Eigen::Vector3d::Zero();
  /// A winch pays the cable out at the base: the winch's link (ChainModel::firstLink()) has length
  /// winch_length and grows at winch_speed, its material sliding out along its axis at that speed.
  bool winch = false;
  double winch_length = 0.0;        ///< [m]
  double winch_deployed = 0.0;      ///< the deployed length L [m]
  double winch_speed = 0.0;         ///< + paying out [m/s]
  double winch_acceleration = 0.0;  ///< [m/s^2]
  /// The ROV body's thrust (load.mode body): force and moment at its origin, body frame [N, N m].
  Eigen::Matrix<double, 6, 1> body_thrust = Eigen::Matrix<double, 6, 1>::Zero();
};

}  // namespace cable_dynamics
