#pragma once
/// \file
/// \brief The cable's equations of motion x' = f(t, x) in coordinates without the zero-elevation
///        singularity: the passes of dynamics/ run in order on one ChainModel and its ChainData.
///
/// Same physical model as PaperModel (n axisymmetric rigid links on ball joints, point load at the
/// tip), plus the fluid, the springs and the end conditions. Each link's state is its unit axis u_k,
/// its total twist about the vertical sigma_k = psi_k + phi_k (the one combination of the paper's
/// angles that stays defined when the link hangs straight down) and its angular velocity omega_k
/// (world/paper frame); see state_layout.h. The accelerations come from the virtual-power balance of
/// everything outboard of each joint; see docs/MODEL.md section 6. Frame: the paper's, z down, origin at
/// the base's rest position.
///
/// One evaluation: forwardPass (applyEnds -> computeAxialTensions -> computeKinematics -> the ROV body ->
/// computeExternalLoads -> computeJointTorques) -> the solver of the model's formulation (solveArticulatedBody, O(n); or solveDense, O(n^3)). derivative() is the hot path
/// of every integrator: it must not allocate (test_no_allocation) and is measured by bench/fluid_step.

#include <Eigen/Core>

#include "cable_dynamics/dynamics/cable_limits.h"
#include "cable_dynamics/dynamics/chain_data.h"
#include "cable_dynamics/dynamics/chain_model.h"
#include "cable_dynamics/dynamics/seabed_contact.h"
#include "cable_dynamics/dynamics/state_layout.h"
#include "cable_dynamics/params/cable_params.h"

namespace cable_dynamics {

/// Everything derived from one state: accelerations, forces along the cable, energies.
struct ChainOutputs {
  Eigen::VectorXd omega_rate;    ///< (3n) angular accelerations [rad/s^2]
  Eigen::Matrix3Xd ends;         ///< (3 x n+1) base and link far ends [m]
  Eigen::Matrix3Xd joint_force;  ///< (3 x n) force on the outboard part at joint k's base end [N]
  /// (3n) the joint springs' generalized forces on the paper coordinates, dV/dq, with the clamps where
  /// the ends have them [N m] (dampers excluded): the node's JointState effort is minus this.
  Eigen::VectorXd spring_force;
  Eigen::VectorXd tension;       ///< (n) force along link k at its base end, + pulls towards the base [N]
                                 ///< (0 on a winch's drum; at the base link: the line pull)
  /// Axial elasticity (empty with rigid links): each link's stretch s_k [m] (its strain is s_k / l_k,
  /// its stretched length l_k + s_k) and the tension its stretch carries at its far end [N] (0: slack).
  Eigen::VectorXd stretch, far_tension;
  Eigen::VectorXd strain;  ///< (n) s_k / l_k [-] (empty with rigid links)
  int slack_links = 0;     ///< slack links: shorter than unstretched (s_k < 0; a locked last link not counted)
  Eigen::Vector3d load_force = Eigen::Vector3d::Zero();  ///< force the cable exerts on the load [N]
  Eigen::Vector3d base_force = Eigen::Vector3d::Zero();  ///< force the cable exerts on the base [N]
  Eigen::Vector3d coupling_force = Eigen::Vector3d::Zero();  ///< PD force of the anchor / ROV on the load [N]
  double kinetic_energy = 0.0;    ///< cable and load, without the fluid's added mass [J]
  double potential_energy = 0.0;  ///< gravity minus buoyancy, zero at the base's rest height [J]
  double elastic_energy = 0.0;    ///< joint springs and the links' stretch [J]
  double contact_energy = 0.0;    ///< the seabed's contact springs [J]
  SeabedReport seabed;            ///< contact forces, grounded length, touchdown (with a seabed)
  /// Bend radii, utilisation against cable.limits, seabed clearance (dynamics/cable_limits.h).
  LimitReport limits;
};

/// The model of one cable and the workspace its evaluations write.
class ChainDynamics {
 public:
  explicit ChainDynamics(const CableParams& params);

  int links() const { return model_.links(); }
  /// The winch deploys slots [first, n) (ChainModel::deploy); between evaluations only.
  void deploy(int first) { model_.deploy(data_.deployed, first); }
  /// Holds joint `joint` (between links joint - 1 and joint, straight and turning together, as just
  /// after the winch's link split there) with the moment across their axis that keeps their relative
  /// angular acceleration across it zero at x: the moment the rigid link held there, so that the
  /// accelerations, and the line pull, are those the unsplit link had; it is let go as the winch pays
  /// out the next kJointHoldLinks links of `span` [m] (ChainDeployment::holdJoint, JointHold), with a damper
  /// of `damping_rate` [1/s] times the joint's relative inertia across the axis. Three solves; between
  /// steps. Returns false (a zero hold) when a solve fails.
  bool holdNewJoint(int joint, const Eigen::VectorXd& x, const EndInputs& ends, double span, double damping_rate);
  /// Drops the holds the ends `ends` let go entirely; between steps.
  void dropReleasedHolds(const EndInputs& ends) {
    if (data_.deployed.jointHolds() == 0) return;
    data_.deployed.setHoldState(ends.time, ends.winch_deployed);
    data_.deployed.dropReleasedHolds();
  }
  /// Drops any hold (a new state).
  void releaseJoints() { data_.deployed.releaseJoints(); }
  /// Replaces the constants by `model` (the same cable: same n; live tuning of its coefficients) and the
  /// deployment by `deployed`, the running one that `model.redeploy` has rebuilt (same first slot, winch
  /// link and holds; the caller checks it before). The workspace keeps its sizes; between evaluations only.
  void replaceModel(const ChainModel& model, const ChainDeployment& deployed) {
    data_.deployed = deployed;
    model_ = model;
  }
  /// What the ends set in the data before any pass: the winch's link length and its held joints' moments
  /// (the deployment), the clamps. Every evaluation calls it; the statics call it to see the cable as the
  /// ends have it now.
  void applyEnds(const EndInputs& ends);
  int stateSize() const { return StateLayout::size(model_.links(), model_.body().active, model_.axial()); }
  const ChainModel& model() const { return model_; }
  /// The cable as deployed now (per-link constants, the winch's link and holds; ChainData::deployed).
  const ChainDeployment& deployed() const { return data_.deployed; }
  const LinkProperties& properties() const { return data_.deployed.properties(); }
  ChainData& data() { return data_; }
  const ChainData& data() const { return data_; }
  CurrentField& current() { return data_.current; }

  /// Sets the paper azimuths (n) [rad] near which the paper springs read psi_k (kept continuous
  /// by the simulator between steps; only the paper stiffness model uses them).
  void setAzimuthReference(const Eigen::VectorXd& psi) { data_.azimuths.reset(psi); }
  /// Moves the azimuth reference to the state's azimuths (unwrapped against it), after each accepted step.
  void followAzimuths(const Eigen::VectorXd& x);

  /// The seabed friction's anchors at state x (static friction; nothing otherwise): at their points
  /// (`slide` false: a new state), or slid to within their reach (`slide` true: after each accepted step;
  /// seabed_contact.h; `winch_links` as there). One kinematics pass. O(n), no allocation.
  void placeContactAnchors(const Eigen::VectorXd& x, const EndInputs& ends, bool slide, int winch_links = 1);
  /// The anchors slid after an accepted step, at the kinematics the last evaluation left in data(): the
  /// caller's promise that it was at the step's end state (CableSimulator::advance ends with one there, for
  /// its energy balance), which saves placeContactAnchors' kinematics pass on every step.
  void slideContactAnchors(int winch_links = 1) { cable_dynamics::placeContactAnchors(model_, data_, true, winch_links); }

  /// x' at state x (size stateSize()). Returns false when the state is not finite, the mass matrix is
  /// not positive definite or an acceleration is not finite; xdot is then unspecified.
  bool derivative(const Eigen::VectorXd& x, const EndInputs& ends, Eigen::VectorXd& xdot);

  /// Accelerations, forces along the cable and energies at x. Returns false like derivative().
  bool evaluate(const Eigen::VectorXd& x, const EndInputs& ends, ChainOutputs& out);

  /// A start whose tip does not move with an exact anchor (ends.target_velocity): x's angular velocities and
  /// stretch rates corrected by the impulse on the tip that makes it (tipVelocityProjection). Returns false
  /// when the correction is not finite (x is then unchanged). Allocates: for starts, not for steps.
  bool matchTipVelocity(Eigen::VectorXd& x, const EndInputs& ends);

  /// The passes before the solver at x (kinematics, external loads, joint springs and dampers) into
  /// data(), and the ends' clamp: what the implicit integrator's own recursion reads. O(n), no allocation.
  void computeLoads(const Eigen::VectorXd& x, const EndInputs& ends);

  /// Kinetic + potential + elastic + seabed contact energy at x [J] without solving for the
  /// accelerations (O(n)). `magnitude` gets the sum of the terms' absolute values [J].
  double mechanicalEnergy(const Eigen::VectorXd& x, const EndInputs& ends, double& magnitude);
  /// The kinematics and the ROV body's terms at x (data().tip_*, data().body), nothing else: what the
  /// body's pose and twist are read from. O(n), no allocation.
  void computeBodyPose(const Eigen::VectorXd& x, const EndInputs& ends);
  /// mechanicalEnergy() of the state x that the last derivative() or evaluate() call was given, from
  /// the kinematics that call left (no second pass over the chain).
  double solvedMechanicalEnergy(const Eigen::VectorXd& x, double& magnitude);

  /// The generalized forces of the dense formulation at x (3n, the right-hand side of
  /// M omega' = rhs) into `out`, with or without the dampers; leaves the kinematics and loads of x in
  /// data() for massMatrix(). O(n). For the semi-implicit integrator's Jacobians.
  void generalizedForces(const Eigen::VectorXd& x, const EndInputs& ends, bool with_dampers, Eigen::VectorXd& out);
  /// The mass matrix (3n x 3n) [kg m^2] at the state of the last generalizedForces() call. O(n^2).
  const Eigen::MatrixXd& massMatrix();

  /// Paper coordinates (3n) and rates (3n) of state x; psi continues from the azimuth reference.
  void paperCoordinates(const Eigen::VectorXd& x, Eigen::VectorXd& q, Eigen::VectorXd& qd) const;
  /// State from paper coordinates: axes, twists, angular velocities (energies zero).
  void stateFromPaper(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, Eigen::VectorXd& x) const;

 private:
  /// How far forwardPass goes: the kinematics (and the ROV body's terms), or on to the loads on every
  /// link (external loads, joint springs and dampers) that a solver reads.
  enum class Stage { kKinematics, kLoads };
  /// The one forward pass every evaluation starts with: the ends into the data (applyEnds), the
  /// stretches, the kinematics, the ROV body's terms, and with Stage::kLoads the external loads and the
  /// joint torques (with the dampers or without). O(n), no allocation.
  void forwardPass(const Eigen::VectorXd& x, const EndInputs& ends, Stage stage, bool with_dampers = true);
  /// The passes up to the accelerations (and all joint forces or only joint 0's).
  bool solve(const Eigen::VectorXd& x, const EndInputs& ends, bool all_joint_forces);
  void writeRates(Eigen::VectorXd& xdot) const;  ///< x' from the solved state, after solve()
  /// The ROV body's terms at x (load.mode body; nothing otherwise), after the kinematics.
  void computeBodyTerms(const Eigen::VectorXd& x, const EndInputs& ends);

  ChainModel model_;
  ChainData data_;
};

}  // namespace cable_dynamics
