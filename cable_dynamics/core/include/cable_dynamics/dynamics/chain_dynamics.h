#pragma once
/// \file
/// \brief The cable's equations of motion in coordinates without the zero-elevation singularity.
///
/// Same physical model as PaperModel (n axisymmetric rigid links on ball joints, point load at the
/// tip), plus the fluid, the springs and the end conditions. Each link's state is its unit axis u_k,
/// its total twist about the vertical sigma_k = psi_k + phi_k (the one combination of the paper's
/// angles that stays defined when the link hangs straight down) and its angular velocity omega_k
/// (world/paper frame). The accelerations come from the virtual-power balance of everything outboard
/// of each joint; see docs/MODEL.md section 6. Frame: the paper's, z down, origin at the base's rest
/// position.

#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <Eigen/Core>
#include <Eigen/StdVector>

#include "cable_dynamics/dynamics/azimuth_tracker.h"
#include "cable_dynamics/params/cable_params.h"
#include "cable_dynamics/dynamics/fluid.h"
#include "cable_dynamics/dynamics/link_block.h"

namespace cable_dynamics {

using Matrix3dVector = std::vector<Eigen::Matrix3d, Eigen::aligned_allocator<Eigen::Matrix3d>>;

/// Layout of the flat state vector x (size 7n + 2).
struct StateLayout {
  static constexpr int kPerLink = 7;  ///< u (3), sigma (1), omega (3)
  static int axis(int k) { return kPerLink * k; }
  static int twist(int k) { return kPerLink * k + 3; }
  static int omega(int k) { return kPerLink * k + 4; }
  static int dissipated(int n) { return kPerLink * n; }  ///< energy taken out by drag, added mass, dampers [J]
  static int workInput(int n) { return kPerLink * n + 1; }  ///< work done by the moving ends [J]
  static int size(int n) { return kPerLink * n + 2; }
};

/// What drives the ends during a step (paper frame).
struct EndInputs {
  Eigen::Vector3d base_position = Eigen::Vector3d::Zero();      ///< [m]
  Eigen::Vector3d base_velocity = Eigen::Vector3d::Zero();      ///< [m/s]
  Eigen::Vector3d base_acceleration = Eigen::Vector3d::Zero();  ///< [m/s^2]
  bool load_coupled = false;                                    ///< PD coupling of the tip to a target
  Eigen::Vector3d target_position = Eigen::Vector3d::Zero();    ///< [m]
  Eigen::Vector3d target_velocity = Eigen::Vector3d::Zero();    ///< [m/s]
};

/// Everything derived from one state: accelerations, forces along the cable, energies.
struct ChainOutputs {
  Eigen::VectorXd omega_rate;    ///< (3n) angular accelerations [rad/s^2]
  Eigen::Matrix3Xd ends;         ///< (3 x n+1) base and link far ends [m]
  Eigen::Matrix3Xd joint_force;  ///< (3 x n) force on the outboard part at joint k's base end [N]
  Eigen::VectorXd tension;       ///< (n) force along link k at its base end, + pulls towards the base [N]
  Eigen::Vector3d load_force = Eigen::Vector3d::Zero();  ///< force the cable exerts on the load [N]
  Eigen::Vector3d base_force = Eigen::Vector3d::Zero();  ///< force the cable exerts on the base [N]
  Eigen::Vector3d coupling_force = Eigen::Vector3d::Zero();  ///< PD force of the anchor / ROV on the load [N]
  double kinetic_energy = 0.0;    ///< cable and load, without the fluid's added mass [J]
  double potential_energy = 0.0;  ///< gravity minus buoyancy, zero at the base's rest height [J]
  double elastic_energy = 0.0;    ///< joint springs [J]
};

/// Equations of motion x' = f(t, x). The hot path is derivative(): by default the O(n) articulated-body
/// recursion (chain_recursive.cpp); with setRecursive(false) the 3n x 3n mass matrix of the angular
/// velocities, assembled in O(n^2) and solved by Cholesky, O(n^3). Neither allocates on the heap.
class ChainDynamics {
 public:
  explicit ChainDynamics(const CableParams& params);

  int links() const { return n_; }
  int stateSize() const { return StateLayout::size(n_); }
  const LinkProperties& properties() const { return props_; }
  CurrentField& current() { return current_; }

  /// Sets the paper azimuths (n) [rad] near which the paper springs read psi_k (kept continuous
  /// by the simulator between steps; only the paper stiffness model uses them).
  void setAzimuthReference(const Eigen::VectorXd& psi) { azimuths_.reset(psi); }

  /// Moves the azimuth reference to the state's azimuths (unwrapped against it), after each accepted step.
  void followAzimuths(const Eigen::VectorXd& x);

  /// true: O(n) articulated-body recursion; false: dense mass matrix and Cholesky (O(n^3)).
  bool recursive() const { return recursive_; }
  void setRecursive(bool recursive);

  /// x' at state x (size stateSize()). Returns false when the state is not finite or the mass matrix
  /// is not positive definite; xdot is then unspecified.
  bool derivative(const Eigen::VectorXd& x, const EndInputs& ends, Eigen::VectorXd& xdot);

  /// One step of length h [s] of the semi-implicit integrator: backward Euler in the angular velocities,
  /// linearized with the Jacobians of the generalized forces (springs, dampers, drag, coupling), then the
  /// orientations advance with the new velocities. First order, but stable for stiff springs and strong
  /// drag. Returns false when a state is not finite or the linear system is singular.
  bool semiImplicitStep(const Eigen::VectorXd& x, const EndInputs& ends, double h, Eigen::VectorXd& next);

  /// Accelerations, forces along the cable and energies at x. Returns false like derivative().
  bool evaluate(const Eigen::VectorXd& x, const EndInputs& ends, ChainOutputs& out);

  /// Kinetic + potential + elastic energy at x [J]: the energies of evaluate() without solving for the
  /// accelerations (O(n)); used to catch a step that created energy. `magnitude` gets the sum of the
  /// three terms' absolute values [J].
  double mechanicalEnergy(const Eigen::VectorXd& x, const EndInputs& ends, double& magnitude);

  /// mechanicalEnergy() of the state x that the last derivative() or evaluate() call was given, from
  /// the kinematics that call left (no second pass over the chain).
  double solvedMechanicalEnergy(const Eigen::VectorXd& x, double& magnitude);

  /// Paper coordinates (3n) and rates (3n) of state x; psi continues from the azimuth reference.
  void paperCoordinates(const Eigen::VectorXd& x, Eigen::VectorXd& q, Eigen::VectorXd& qd) const;

  /// State from paper coordinates: axes, twists, angular velocities (base at rest, energies zero).
  void stateFromPaper(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, Eigen::VectorXd& x) const;

 private:
  bool solve(const Eigen::VectorXd& x, const EndInputs& ends, bool all_joint_forces);
  void kinematics(const Eigen::VectorXd& x, const EndInputs& ends);
  void externalForces(const EndInputs& ends);
  void inertiaTensors();  ///< A_k per link (O(n))
  /// Angular accelerations into LinkBlock::omega_rate, the load force, the added-mass power and the
  /// joint forces (all of them, or only joint 0's, which the input power needs) by the articulated-body
  /// recursion (O(n); chain_recursive.cpp).
  void solveRecursive(bool all_joint_forces);
  /// The constants of links_ (normal added mass per length [kg/m], cable radius [m]), and the padding lanes.
  void fillLinkConstants(double added_per_length, double radius);
  /// Sizes the dense formulation's and the semi-implicit integrator's 3n x 3n workspace, once: at
  /// construction when the configuration uses either, else on first use (outside any step's loop).
  void allocateDense();
  /// Power of the added-mass force on link k [W], from its base-end and axis accelerations.
  double addedMassPower(int k, const Eigen::Vector3d& base_acc, const Eigen::Vector3d& axis_acc) const;
  void assembleForces();  ///< tensors, outboard sums and the right-hand side rhs_ (O(n))
  void assembleMass();    ///< the mass matrix (O(n^2)), after assembleForces()
  /// Generalized forces (rhs of M omega' = rhs) at x: O(n), no mass matrix.
  void generalizedForces(const Eigen::VectorXd& x, const EndInputs& ends, Eigen::VectorXd& out);
  void jointForces();
  void writeRates(Eigen::VectorXd& xdot) const;  ///< x' from the solved state, after solve()
  bool finiteAngularAccelerations() const;       ///< after solve(): every LinkBlock::omega_rate finite
  void computeJointTorques(const Eigen::VectorXd& x);
  void paperSpringTorques(const Eigen::VectorXd& x);
  void bendingSpringTorques(const Eigen::VectorXd& x);
  double elasticEnergy(const Eigen::VectorXd& x);
  void kineticAndPotential(double& kinetic, double& potential) const;

  int n_;
  LinkProperties props_;
  StiffnessModel stiffness_model_;
  CurrentField current_;
  double density_, diameter_;
  LinkDrag drag_;
  double load_drag_area_, load_coupling_stiffness_, load_coupling_damping_;

  // Per link constants: in links_ (LinkBlock's first fields).
  double load_inertia_;                  ///< load mass plus its added mass [kg]
  double load_weight_;                   ///< [N]
  AzimuthTracker azimuths_;              ///< continuous paper azimuths, followed after each accepted step

  // Workspace (sized once).
  LinkBlocks links_;  ///< per-link constants, kinematics, loads and the recursion's terms, 8 links a block
  Eigen::Matrix3Xd inertial_force_, inertial_moment_, axis_acc_;
  Matrix3dVector tensor_;                ///< A_k = m' I + m_a' (I - u u^T) per length [kg/m]
  Matrix3dVector outboard_;              ///< B_k = sum_{j>k} l_j A_j + load [kg]
  Matrix3dVector column_;                ///< E_j [u_j]x, shared by column j of M
  Eigen::Vector3d tip_pos_, tip_vel_, tip_known_acc_, load_external_, coupling_;
  Eigen::MatrixXd mass_matrix_;
  Eigen::VectorXd rhs_;
  Eigen::LLT<Eigen::MatrixXd> llt_;
  Eigen::Matrix3Xd joint_force_;
  Eigen::Vector3d load_force_;
  double drag_power_ = 0.0, added_mass_power_ = 0.0, input_power_ = 0.0;
  Eigen::Matrix3Xd spring_torque_, damping_torque_;  ///< (3 x n) [N m]; LinkBlock::torque is their sum
  Eigen::VectorXd paper_psi_;                        ///< (n) absolute azimuths [rad]
  Eigen::Matrix3Xd link_base_acc_;                   ///< (3 x n) acceleration of each link's base end [m/s^2]
  // Semi-implicit integrator workspace.
  Eigen::MatrixXd jacobian_velocity_, jacobian_rotation_, system_;  ///< (3n x 3n)
  Eigen::VectorXd perturbed_, force_plus_, force_minus_, velocity_, step_rhs_, delta_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  bool skip_damping_ = false;  ///< generalized forces without the dampers (the stiffness Jacobian)
  bool recursive_ = true;
  bool has_springs_ = false;  ///< any joint spring or damper at all
  Eigen::VectorXd paper_q_, paper_qd_;  ///< (3n) paper coordinates and rates for the paper springs
};

}  // namespace cable_dynamics
