#pragma once
/// \file
/// \brief The articulated-body recursion with "effective inertia" terms, for the linearly implicit
///        integrator (docs/MODEL.md section 6, "Implicit integrator"): it solves
///        (M + c_D D + c_K K) omega' = rhs in O(n), where D and K are the velocity and rotation
///        Jacobians of the stiff forces, each local to a joint, a link or the load:
///        - joint k's springs and dampers (bending model): 3x3 blocks on the relative rotation of link k
///          to link k-1 (or to the clamp), K_j = k_b (I - m m^T) + k_t m m^T, D_j = c_e (I - m m^T) +
///          c_t m m^T with m the joint's mean axis. They become the joint's impedance: the joint passes
///          the force rigidly and a torque -(c_D D_j + c_K K_j) nu for a relative angular acceleration nu.
///        - link k's drag, linearized in the link's spatial velocity (angular velocity, base-end velocity):
///          a 6x6 damping added to the link's spatial inertia about its base end;
///        - link k's geometric stiffness from the tension: the moment of the outboard loads about the
///          base end turns with the link, K_g = (G . u) (I - u u^T), G = l F_outboard + first moment of
///          the link's own loads (gravity's stiffness of a hanging chain exactly; clipped at 0 in compression);
///        - the load's drag Jacobian and its PD coupling (k_c, c_c) added to the load's mass;
///        - the seabed's contact at each link's points in the bed (seabed_contact.h): the normal spring
///          share k n n^T and damper, and the friction's secant damping N / max(|slip|, v_r) (the
///          regularized viscous band: the stiff part) over the tangent plane, as a 6x6 stiffness and a
///          6x6 damping of the link about its base end (the load's point contact as a 3x3 pair);
///        - a clamped tip's bend spring and damper: 3x3 blocks k (I - m m^T), c (I - m m^T) on the last
///          link's rotation relative to the clamp (m: the mean of its axis and the clamp's; no twist: a
///          swivel), added to that link's rotational inertia.
///
/// Unlike articulated_body.cpp, whose joints pass no torque (so spin and the two transverse directions
/// separate, and 3x3 blocks suffice), here each joint passes a torque through its impedance, so the
/// outboard part shows its parent a 6x6 articulated inertia (rotation and translation of the joint point,
/// world axes). Every per-link quantity is sized in the constructor: no heap allocation in solve().

#include <vector>

#include <Eigen/Core>
#include <Eigen/StdVector>

#include "cable_dynamics/dynamics/chain_data.h"
#include "cable_dynamics/dynamics/chain_model.h"
#include "cable_dynamics/dynamics/state_layout.h"

namespace cable_dynamics {

/// The Jacobian terms of one link and its joint, and the recursion's results for it (SI units).
struct StiffLinkTerms {
  Eigen::Matrix3d joint_stiffness = Eigen::Matrix3d::Zero();  ///< K_j of joint k (to link k-1 or the clamp) [N m/rad]
  Eigen::Matrix3d joint_damping = Eigen::Matrix3d::Zero();    ///< D_j [N m s/rad]
  /// Drag damping over (omega, v_base): torque about the base end per omega [N m s], per v_base [N s],
  /// force per v_base [N s/m] (force per omega is drag_rv^T).
  /// The seabed's damping adds to them.
  Eigen::Matrix3d drag_rr = Eigen::Matrix3d::Zero(), drag_rv = Eigen::Matrix3d::Zero(), drag_vv = Eigen::Matrix3d::Zero();
  bool in_contact = false;  ///< the link's seabed stiffness (StiffContactTerms) is not zero
  /// The far half's skin friction on the far-end point (axial elasticity): its damping along u per unit
  /// of the point's velocity [N s/m], and what the stage adds to the point's right-hand side [N].
  double far_damping = 0.0;
  Eigen::Vector3d far_extra = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  ///< u at the linearization
  double geometric = 0.0;  ///< G . u, the geometric stiffness across the link [N m/rad]
  Eigen::Vector3d extra_torque = Eigen::Vector3d::Zero();  ///< added to the right-hand side: about the base end [N m]
  Eigen::Vector3d extra_force = Eigen::Vector3d::Zero();   ///< [N]
  // Backward pass: nu = -(forward_rot a_rot + forward_lin a_lin) - nu_bias for the parent's motion a.
  Eigen::Matrix3d forward_rot = Eigen::Matrix3d::Zero(), forward_lin = Eigen::Matrix3d::Zero();
  Eigen::Vector3d nu_bias = Eigen::Vector3d::Zero();  ///< [rad/s^2]
  // Forward pass.
  Eigen::Vector3d angular_acc = Eigen::Vector3d::Zero();  ///< omega' [rad/s^2]
  Eigen::Vector3d delta_acc = Eigen::Vector3d::Zero();    ///< d_k: base-end acceleration less the known one [m/s^2]
  // The link's own force rows, kept for the joint forces: force = own_vr alpha + own_vv d + own_bias.
  Eigen::Matrix3d own_vr = Eigen::Matrix3d::Zero(), own_vv = Eigen::Matrix3d::Zero();
  Eigen::Vector3d own_bias = Eigen::Vector3d::Zero();  ///< [N]
  Eigen::Vector3d far_bias = Eigen::Vector3d::Zero();  ///< the far-end point's m_f a0_far - w_f e_z (axial elasticity) [N]
  double tension = 0.0;  ///< at the base end, -J_k . u_k, from the last solve() [N]
  // Axial elasticity: the prismatic joint at the far end (docs/MODEL.md section 12) with its impedance
  // cd c + ck k (c, k: the stretch law's derivatives, 0 while slack).
  double lever = 0.0;          ///< l + s, base end to far end [m]
  double stretch_spring = 0.0, stretch_damper = 0.0;  ///< k = EA / l [N/m], c = c_a / l [N s/m]; 0 while it stays slack
  double stretch_extra = 0.0;  ///< added to the joint's force along u, as a tension's decrease [N]
  Eigen::Vector3d stretch_rot = Eigen::Vector3d::Zero(), stretch_lin = Eigen::Vector3d::Zero();  ///< rv u, vv u
  double stretch_inverse = 0.0;  ///< 1 / (u^T vv u + cd c + ck k) [1/kg]
  double stretch_bias = 0.0;     ///< u . p_v + T - extra [N]
  double stretch_acc = 0.0;      ///< s'' [m/s^2]
};

/// A link's seabed stiffness over (rotation, base-end displacement), laid out as the drag's damping
/// [N m/rad], [N/rad], [N/m]. Kept apart from StiffLinkTerms: most links of most cables never touch, and
/// the recursion's per-link terms stay as compact as without a seabed.
struct StiffContactTerms {
  Eigen::Matrix3d rr = Eigen::Matrix3d::Zero(), rv = Eigen::Matrix3d::Zero(), vv = Eigen::Matrix3d::Zero();
};

/// Terms and solver of the implicit step for one chain. Call linearize() after ChainDynamics::computeLoads(),
/// then clearExtra() / addJacobianTimes() to build the right-hand side, then solve().
class StiffArticulatedBody {
 public:
  explicit StiffArticulatedBody(int links);

  /// Joint, drag, geometric and load Jacobians at the state whose loads `data` holds. O(n). The geometric
  /// stiffness reads the tensions of the last solve() (inertial forces included: a whipping cable's
  /// tension is mostly centripetal) when `use_last_tension`, else the tension the external loads alone
  /// would hold statically.
  void linearize(const ChainModel& model, const ChainData& data, const EndInputs& ends, bool use_last_tension = false);

  /// The geometric stiffness alone, from the tensions of the last solve() (as linearize() with
  /// `use_last_tension`): the other terms are kept.
  void geometricFromLastTension(const ChainModel& model, const ChainData& data);

  /// Axial elasticity: each stretch's spring and damper for the matrix at the state of `data`, kept until
  /// the next call (a step's two stages share them: switched between its stages, a link coming taut made
  /// the step unstable). A link stays out while it is clearly slack over `horizon` [s] (the step).
  void linearizeStretches(const ChainModel& model, const ChainData& data, double horizon);
  /// Sets the extra right-hand side to zero.
  void clearExtra();
  /// Axial elasticity: adds stiffness_factor k r + damping_factor c r' (each link's stretch law's
  /// derivatives from linearize()) to the right-hand side of each stretch, r being a stretch (n) [m] and
  /// r' a stretch rate (n) [m/s].
  void addStretchJacobianTimes(const ChainModel& model, const ChainData& data, double stiffness_factor, double damping_factor,
                               const Eigen::VectorXd& stretch, const Eigen::VectorXd& rate);
  /// Adds stiffness_factor K r + damping_factor D r to the right-hand side, as generalized forces:
  /// r is a rotation (or rotation rate) of each link, `rotation` (3 x n) [rad or rad/s], with
  /// `base_rotation` the base clamp's and `tip_rotation` a clamped tip's (the springs act on the
  /// differences), a translation of each base end `translation` (3 x n) (the drag's damping and the
  /// seabed read it) and of the tip, `tip_translation` (relative to the target when coupled).
  void addJacobianTimes(const ChainModel& model, const ChainData& data, double stiffness_factor, double damping_factor,
                        const Eigen::Matrix3Xd& rotation, const Eigen::Vector3d& base_rotation,
                        const Eigen::Vector3d& tip_rotation, const Eigen::Matrix3Xd& translation,
                        const Eigen::Vector3d& tip_translation);

  /// Solves (M + damping_weight D + stiffness_weight K) omega' = rhs + extra at the state of `data`
  /// (rhs: everything computeLoads() put there, as the ordinary recursion reads it). Results in
  /// link(k).angular_acc, link(k).delta_acc, tipDelta(), baseForce(). O(n), no heap allocation.
  void solve(const ChainModel& model, const ChainData& data, double damping_weight, double stiffness_weight);

  const StiffLinkTerms& link(int k) const { return links_[k]; }
  /// Link k's seabed stiffness (zero unless link(k).in_contact).
  const StiffContactTerms& contact(int k) const { return contact_[k]; }
  /// d at the tip: the load's acceleration is tip_known_acc + tipDelta() [m/s^2].
  const Eigen::Vector3d& tipDelta() const { return tip_delta_; }
  /// A clamped tip's blocks on the last link's rotation relative to the clamp (zero unless clamped).
  const Eigen::Matrix3d& tipClampStiffness() const { return tip_clamp_stiffness_; }
  const Eigen::Matrix3d& tipClampDamping() const { return tip_clamp_damping_; }
  /// The load's seabed contact blocks on its displacement (zero off the bed).
  const Eigen::Matrix3d& loadContactStiffness() const { return load_contact_stiffness_; }
  /// Force the base exerts on the base link at its base end [N] (the joint force J of the base link).
  const Eigen::Vector3d& baseForce() const { return base_force_; }

 private:
  /// Link k's seabed stiffness and damping (added to its drag's) at the state of `data`.
  void linearizeContact(const ChainModel& model, const ChainData& data, int k, StiffLinkTerms& t, StiffContactTerms& contact);

  std::vector<StiffLinkTerms, Eigen::aligned_allocator<StiffLinkTerms>> links_;
  std::vector<StiffContactTerms, Eigen::aligned_allocator<StiffContactTerms>> contact_;
  Eigen::Matrix3d load_drag_ = Eigen::Matrix3d::Zero();  ///< load drag's damping [N s/m]
  double coupling_stiffness_ = 0.0, coupling_damping_ = 0.0;  ///< of the PD coupling, when coupled
  /// The load's seabed contact: its normal spring and damper, its friction's secant damping [N/m], [N s/m].
  Eigen::Matrix3d load_contact_stiffness_ = Eigen::Matrix3d::Zero(), load_contact_damping_ = Eigen::Matrix3d::Zero();
  Eigen::Vector3d load_extra_ = Eigen::Vector3d::Zero();  ///< extra force on the load [N]
  /// A clamped tip's blocks on the last link's rotation relative to the clamp [N m/rad], [N m s/rad].
  Eigen::Matrix3d tip_clamp_stiffness_ = Eigen::Matrix3d::Zero(), tip_clamp_damping_ = Eigen::Matrix3d::Zero();
  Eigen::Vector3d tip_delta_ = Eigen::Vector3d::Zero(), base_force_ = Eigen::Vector3d::Zero();
  double tip_tension_ = 0.0;  ///< the load's pull along the last link [N]
};

}  // namespace cable_dynamics
