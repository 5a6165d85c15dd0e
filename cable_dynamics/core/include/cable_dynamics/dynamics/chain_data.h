#pragma once
/// \file
/// \brief Everything the dynamics write while evaluating one state: the "data" half of the model/data
///        split, sized once from a ChainModel, so that no evaluation allocates.

#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/StdVector>

#include "cable_dynamics/dynamics/azimuth_tracker.h"
#include "cable_dynamics/dynamics/chain_deployment.h"
#include "cable_dynamics/dynamics/chain_model.h"
#include "cable_dynamics/dynamics/fluid.h"
#include "cable_dynamics/dynamics/forces/contact.h"
#include "cable_dynamics/dynamics/link_block.h"

namespace cable_dynamics {

using Matrix3dVector = std::vector<Eigen::Matrix3d, Eigen::aligned_allocator<Eigen::Matrix3d>>;

/// The dense formulation's workspace (dense_solver.cpp): 3n x 3n, so only allocated when it is used
/// (the paper formulation, or the semi-implicit integrator that needs the mass matrix).
struct DenseWorkspace {
  Eigen::MatrixXd mass_matrix;       ///< (3n x 3n) of the angular velocities [kg m^2]
  Eigen::VectorXd rhs;               ///< (3n) generalized forces [N m]
  Eigen::VectorXd omega_rate;        ///< (3n) solved angular accelerations [rad/s^2]
  Eigen::LLT<Eigen::MatrixXd> llt;   ///< Cholesky factor of mass_matrix
  Matrix3dVector tensor;             ///< (n) l_k A_k + attachments, A_k = m' I + m_a' (I - u u^T) [kg]
  Matrix3dVector outboard;           ///< (n) B_k = sum_{j>k} tensor_j + load [kg]
  Matrix3dVector column;             ///< (n) E_j [u_j]x, shared by column j of M [kg m]
  Eigen::Matrix3Xd inertial_force;   ///< (3 x n) A (l a0 + l^2/2 beta) [N]
  Eigen::Matrix3Xd inertial_moment;  ///< (3 x n) its first moment [N m]
  Eigen::Matrix3Xd axis_acc;         ///< (3 x n) u'' [1/s^2]
  Eigen::Matrix3Xd link_base_acc;    ///< (3 x n) acceleration of each link's base end [m/s^2]

  bool allocated() const { return mass_matrix.rows() > 0; }
  void allocate(int links);
};

/// The per-evaluation state of the dynamics of one ChainModel: kinematics, loads, the recursion's terms,
/// forces along the cable, powers, and the inputs that persist between evaluations (the current, the
/// azimuth tracker). Sized once in the constructor.
struct ChainData {
  explicit ChainData(const ChainModel& model);

  /// The cable as the winch has deployed it now: the per-link constants every pass reads, and the winch's
  /// held joints. Written only by the model (ChainModel::deploy, setWinchLinkLength, redeploy); without a
  /// winch it stays as constructed.
  ChainDeployment deployed;

  LinkBlocks links;  ///< per-link kinematics, loads and recursion terms, eight links a block

  // Tip (the load) [m], [m/s], [m/s^2]: from the kinematics.
  Eigen::Vector3d tip_position = Eigen::Vector3d::Zero();
  Eigen::Vector3d tip_velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d tip_known_acc = Eigen::Vector3d::Zero();  ///< at zero angular accelerations
  // Load forces [N]: from the external loads; load_force after the solve.
  Eigen::Vector3d load_external = Eigen::Vector3d::Zero();  ///< weight, drag and coupling on the load
  Eigen::Vector3d coupling = Eigen::Vector3d::Zero();       ///< PD force of the anchor / ROV on the load
                                                            ///< (an exact anchor: its constraint force)
  /// An exact anchor (ChainModel::heldTip()): the tip's acceleration the hold's force must give, the
  /// anchor's less the drift correction (external_loads.cpp) [m/s^2].
  Eigen::Vector3d tip_demand = Eigen::Vector3d::Zero();
  Eigen::Vector3d load_force = Eigen::Vector3d::Zero();     ///< force the cable exerts on the load
  RovBodyTerms body;  ///< the ROV body's terms (load.mode body: rov_body.h)

  Eigen::Matrix3Xd joint_force;     ///< (3 x n) force on the outboard part at joint k's base end [N]
  Eigen::Matrix3Xd spring_torque;   ///< (3 x n) joint springs on each link [N m]
  Eigen::Matrix3Xd damping_torque;  ///< (3 x n) joint dampers on each link [N m]

  // The base's clamp for this evaluation (the model's, or turned with the vessel: EndInputs), and the
  // torque its springs and dampers put on the base link [N m] (the vessel's reaction is minus it).
  Eigen::Vector3d clamp_axis = Eigen::Vector3d::UnitZ();
  double clamp_twist = 0.0;
  Eigen::Vector3d clamp_omega = Eigen::Vector3d::Zero();  ///< [rad/s]
  Eigen::Vector3d clamp_torque = Eigen::Vector3d::Zero();
  // The tip's clamp (a clamped tip), and the torque it holds the last link with [N m].
  Eigen::Vector3d tip_clamp_axis = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d tip_clamp_omega = Eigen::Vector3d::Zero();  ///< [rad/s]
  Eigen::Vector3d tip_clamp_torque = Eigen::Vector3d::Zero();
  /// computeJointTorques wrote a winch's held joints' moments into the links' torques in a model that has
  /// no springs (the next evaluation without holds clears them).
  bool holds_written = false;

  // Powers [W]: of the drag, of the added-mass force, of the moving base and the coupling.
  double drag_power = 0.0, added_mass_power = 0.0, input_power = 0.0;
  /// Power the seabed's dampers and friction take out [W]: >= 0, but for a sticking point's anchor spring
  /// giving back what it stored.
  double contact_dissipation = 0.0;
  /// The seabed friction's anchors (static friction; seabed_contact.h), moved only between steps.
  ContactAnchors anchors;

  // The paper springs' scratch: paper coordinates, rates (3n) [rad, rad/s], absolute azimuths (n) [rad].
  Eigen::VectorXd paper_q, paper_qd, paper_psi;

  CurrentField current;     ///< the water's current (input; replaced by a topic or a reset)
  AzimuthTracker azimuths;  ///< continuous paper azimuths, followed after each accepted step
  DenseWorkspace dense;     ///< allocated only when used
};

}  // namespace cable_dynamics
