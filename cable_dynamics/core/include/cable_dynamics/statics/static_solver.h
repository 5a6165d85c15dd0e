#pragma once
/// \file
/// \brief Static equilibrium of the cable: the rest shape whose every link has zero angular
///        acceleration under the same loads the dynamics apply (weight, buoyancy, the Morison drag of a
///        steady current, the load, its coupling spring, the bending model's joint springs).
///
/// Method (static_solver.cpp; docs/MODEL.md section 7): Newton's method in maximal coordinates, O(n)
/// work per iteration. Per deployed link k the unknowns are z_k = (J_k (3), theta_k (2), p_k (3)):
/// J_k the force the inboard part exerts on everything outboard of link k's base end [N] (ChainData's
/// joint force), theta_k a small rotation of the unit axis u_k in its normal plane [rad] and p_k its
/// base end [m]. Per link the equations are
///   force balance        J_k - J_{k+1} + F_k(u_k, p_k) = 0                               (3, [N])
///   moment about p_k     u_k x (N_k - l_k J_{k+1}) + tau_k(u_{k-1}, u_k, u_{k+1}) = 0    (2, [N m])
///   chain closure        p_k - p_{k-1} - l_{k-1} u_{k-1} = 0   (p_0 = the base)          (3, [m])
/// with F_k, N_k the external force on the link and its first moment about the base end, tau_k the
/// joint springs' torque, and past the last link J_n = -F_load(p_tip), the load's weight, drag and
/// coupling spring. The Jacobian is block tridiagonal (8 x 8 blocks), built by central differences
/// block by block and solved by block LU (block Thomas), with a backtracking line search on the
/// residual norm. Starting guess: the limp chain swept from the tip (exact without springs); with a
/// coupled tip the tip force of that sweep is found first by a 3-unknown Newton (shooting) so that the
/// tip meets the coupling spring; with springs and a free tip the straight cable along the clamp. When
/// Newton stalls, continuation on the spring stiffness. A limp uniform line on an exact anchor on a flat
/// bed starts from its elastic catenary with a grounded part instead (catenary_start.h; no continuation
/// on the bed's contact).
///
/// Convergence: max over links of |force residual| / F, |moment residual| / (F l_k) and
/// |closure residual| / l_k below `tolerance`, where F [N] is the sum of the magnitudes of every
/// external force (each link's weight and drag, the load's weight, drag and coupling force) at the
/// iterate. Frame: the paper's, z down.

#include <string>

#include <Eigen/Core>

#include "cable_dynamics/dynamics/chain_model.h"
#include "cable_dynamics/dynamics/fluid.h"

namespace cable_dynamics {

/// What holds the ends (paper frame, z down, origin at the base's rest position).
struct StaticProblem {
  Eigen::Vector3d base_position = Eigen::Vector3d::Zero();    ///< [m]
  bool tip_coupled = false;  ///< load modes anchored / attached: the PD coupling spring to the target
  Eigen::Vector3d target_position = Eigen::Vector3d::Zero();  ///< [m]
  /// Links [first_link, n) are deployed, the first of them leaving the base (and its clamp); the
  /// others are not part of the problem (a winch's drum). 0 = all.
  int first_link = 0;
  /// The base's clamp turned with the vessel (EndInputs::clamp_*): its unit axis and twist [rad] in place
  /// of the model's LinkProperties::clamp_axis and clamp_twist.
  bool clamp_moves = false;
  Eigen::Vector3d clamp_axis = Eigen::Vector3d::UnitZ();
  double clamp_twist = 0.0;
  /// A clamped tip turned with the ROV (EndInputs::tip_clamp_*): its axis in place of the model's
  /// LinkProperties::tip_clamp_axis.
  bool tip_clamp_moves = false;
  Eigen::Vector3d tip_clamp_axis = Eigen::Vector3d::UnitZ();
  /// Axial elasticity: each link's stretch s_k [m] (n entries; empty: none), its far end l + s from its
  /// base. solveStatics sets it itself for a model that stretches (the elastic iteration).
  Eigen::VectorXd stretch;
};

struct StaticOptions {
  double tolerance = 1e-9;  ///< relative residual (see the file comment)
  int max_iterations = 100; ///< Newton iterations, over all continuation steps
  /// A limp uniform line on an exact anchor starts from its elastic catenary (catenary_start.h) rather
  /// than from the line hanging through the bed and the bed's contact ramped up: the same equilibrium in a
  /// third of the iterations on MoorDyn's chains. false: the general start (tests compare the two).
  bool catenary_start = true;
};

struct StaticSolution {
  bool converged = false;
  int iterations = 0;       ///< Newton iterations taken (the starting guess's sweeps not counted)
  double residual = 0.0;    ///< relative residual reached (see the file comment)
  std::string message;      ///< why not, when not converged; empty otherwise
  Eigen::Matrix3Xd axes;    ///< (3 x n) unit axes, paper frame; (0, 0, 1) for links before first_link
  Eigen::VectorXd twists;   ///< (n) sigma_k [rad]: every joint's twist zero (0 before first_link)
  Eigen::VectorXd tension;  ///< (n) axial force at each link's base end, + pulling toward the base [N]
  Eigen::Matrix3Xd joint_force;  ///< (3 x n) force on the outboard part at each link's base end [N]
  Eigen::Vector3d tip_position = Eigen::Vector3d::Zero();  ///< [m]
  Eigen::Vector3d tip_force = Eigen::Vector3d::Zero();  ///< the cable's force on the load [N]
  /// The anchor's or the coupling's force on the load at the solution [N] (zero for a free tip): an exact
  /// anchor's reaction.
  Eigen::Vector3d hold_force = Eigen::Vector3d::Zero();
  /// Axial elasticity: each link's stretch at equilibrium, s_k = T_k l_k / EA_k with T_k the tension at
  /// its far end [m] (n; empty with rigid links), and the fixed-point sweeps that found it.
  Eigen::VectorXd stretch;
  /// Axial elasticity: the far half of each link's skin friction in the current, on its far-end point [N]
  /// (n; zero without far-end points), part of the tension at the far end.
  Eigen::VectorXd far_drag;
  int elastic_sweeps = 0;
};

/// Solves for the static equilibrium. Supports the bending stiffness model and a limp cable (either
/// model with no springs); the paper model's springs act on the paper angles, whose azimuth and
/// torsion terms have no rest shape off the vertical: refused with a message. Not converged, with a
/// message, when a coupled target lies farther from the base than the deployed cable is long (the
/// coupling spring stands in for a rigid hold, which could not reach it).
StaticSolution solveStatics(const ChainModel& model, const ChainDeployment& deployed, const CurrentField& current,
                            const StaticProblem& problem, const StaticOptions& options = {});

/// The solved shape at rest into the state x (dynamics/state_layout.h, already of its size): every
/// link's axis and twist, zero angular velocities, and the stretches at rest (axial elasticity: the
/// state's last 2n entries); the energy accumulators are left as they are.
void setRestState(const StaticSolution& solution, Eigen::VectorXd& x);

}  // namespace cable_dynamics
