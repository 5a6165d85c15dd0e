#pragma once
/// \file
/// \brief Time stepping of the cable: a time scheme, the end conditions, divergence detection and
///        recovery, and the outputs users read (paper angles, link ends, tension, energies). ROS-free.

#include <limits>
#include <memory>
#include <string>

#include <Eigen/Core>

#include "cable_dynamics/dynamics/chain_dynamics.h"
#include "cable_dynamics/params/cable_params.h"
#include "cable_dynamics/simulation/body_motion.h"
#include "cable_dynamics/simulation/end_conditions.h"
#include "cable_dynamics/simulation/link_frames.h"
#include "cable_dynamics/simulation/stable_step.h"
#include "cable_dynamics/simulation/station_keeper.h"
#include "cable_dynamics/simulation/step_check.h"
#include "cable_dynamics/simulation/time_schemes/time_scheme.h"
#include "cable_dynamics/statics/static_solver.h"

namespace cable_dynamics {

/// The ROV's side of an attached load's coupling, for an ROV simulator that couples implicitly
/// (docs/ROV_COUPLING.md): the wrench the cable puts on the ROV at the attachment point and its
/// derivatives, all in the axes of one frame: the paper frame in a SimulationSnapshot (z down, from the
/// base's rest position), the world frame (z up) in the node's message (paperToWorld, paperToWorldMap).
/// Between two messages the ROV applies
///   [F; M](x, v) = [force; moment] + stiffness [x - point; rotation] + damping [v - velocity; omega]
/// with x, v the attachment point's position and velocity and rotation, omega the ROV's small rotation
/// and angular velocity since. Zero unless load.mode is attached.
struct CouplingPort {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();     ///< attachment point the wrench is taken at [m]
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  ///< its velocity as the simulator holds it [m/s]
  Eigen::Vector3d force = Eigen::Vector3d::Zero();     ///< on the ROV [N]
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();    ///< on the ROV about the point [N m]
  /// d[F; M] / d[x; rotation], rows force then moment, columns translation then rotation
  /// [N/m, N/rad; N m/m, N m/rad]. The rotational blocks are zero: a pinned tip passes no moment, and a
  /// clamped tip's bending moment is not linearized here yet.
  Eigen::Matrix<double, 6, 6> stiffness = Eigen::Matrix<double, 6, 6>::Zero();
  /// d[F; M] / d[v; omega] [N s/m, N s/rad; N m s/m, N m s/rad], same layout and the same limit.
  Eigen::Matrix<double, 6, 6> damping = Eigen::Matrix<double, 6, 6>::Zero();
};

/// A port in paper axes (a snapshot's) in world axes, the point still from the base's rest position: what
/// the node publishes (frames.h paperToWorld, paperToWorldMap).
CouplingPort portInWorldAxes(const CouplingPort& paper);

/// Everything published about one instant, all of it in one frame: the paper frame (z down, origin at the
/// base's rest position), which the dynamics compute in; quantities in a body's own axes say so. Adapters
/// that publish in the world frame (REP-103, z up) convert at their boundary with frames.h
/// (paperToWorld, paperToWorldAttitude, paperToWorldMap): the node does, cable_sim's CSV does not.
struct SimulationSnapshot {
  double time = 0.0;       ///< simulated time since reset [s]
  Eigen::VectorXd q;       ///< (3n) paper coordinates [rad]
  Eigen::VectorXd qd;      ///< (3n) their rates [rad/s]
  ChainOutputs chain;      ///< ends, tension, forces, energies
  double largest_tension = 0.0;  ///< axial elasticity: CableSimulator::largestTension() [N]
  long snaps = 0;                ///< axial elasticity: CableSimulator::snaps()
  Eigen::Matrix3Xd axes;   ///< (3 x n) unit axis of each link, base end to far end [-]
  Eigen::VectorXd twists;  ///< (n) each link's total twist about the vertical, sigma = psi + phi [rad]
  /// (n each) Each link's frame (origin at its base end, z along the link, at its stretched length with
  /// axial elasticity) and the URDF's two intermediate frames between neighbours (after the azimuth and
  /// the elevation joint), paper frame (link_frames.h): computed once, by the simulator, for the TF frames,
  /// the URDF and the markers.
  PoseVector link_frames, after_azimuth, after_elevation;
  double dissipated_energy = 0.0;  ///< taken out by drag, added mass, dampers and the seabed since reset [J]
  double work_input = 0.0;         ///< done on the cable by the moving base and the load coupling [J]
  /// kinetic + potential + elastic + seabed contact + dissipated - work input: constant up to the
  /// integrator's error [J]
  double total_energy = 0.0;
  // The winch (zero and the configured length without one).
  int first_link = 0;            ///< the base link's slot: slots before it are on the drum
  double deployed_length = 0.0;  ///< [m]
  double winch_speed = 0.0;      ///< + paying out [m/s]
  double line_pull = 0.0;        ///< tension at the winch, the base link's base end [N]
  // The ends as bodies (paper frame; body axes as the attitudes give them).
  Eigen::Quaterniond vessel_attitude = Eigen::Quaterniond::Identity();  ///< paper frame from vessel axes
  Eigen::Quaterniond rov_attitude = Eigen::Quaterniond::Identity();     ///< paper frame from ROV axes
  /// The vessel's and the ROV's origins [m]: the hang-off point less the hang-off offset; the ROV's target
  /// (the tip, when free) less the attachment offset.
  Eigen::Vector3d vessel_origin = Eigen::Vector3d::Zero(), rov_origin = Eigen::Vector3d::Zero();
  /// The cable's force on the vessel at the hang-off point, about the vessel's origin, in paper and in
  /// vessel axes [N], [N m].
  BodyWrench vessel;
  /// The cable's force on the ROV at the attachment point (the coupling's reaction when attached; the
  /// load's force otherwise), about the ROV's origin, in paper and in ROV axes [N], [N m].
  BodyWrench rov;
  /// The coupling's port at the attachment point, with its stiffness and damping (attached mode), paper axes.
  CouplingPort port;
  /// The ROV body (load.mode body; zero otherwise): its origin's velocity (paper axes) [m/s], its angular
  /// velocity (body frame) [rad/s], the thrust it applies at its origin (body frame; commanded plus station
  /// keeping) [N, N m], and its kinetic and potential energy (in chain's energies too) [J].
  Eigen::Vector3d rov_velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d rov_angular_velocity = Eigen::Vector3d::Zero();
  Eigen::Matrix<double, 6, 1> rov_thrust = Eigen::Matrix<double, 6, 1>::Zero();
};

/// Outcome of one step.
struct StepReport {
  bool ok = true;
  int substeps = 1;     ///< > 1 when the step was retried in smaller pieces after diverging (a
                        ///< start-up's planned pieces, CableSimulator::kStartupPieces, are not counted)
  std::string message;  ///< why the step failed (time and state), empty when ok
};

/// What a simulator is built for, and so which checks its constructor runs.
enum class SimulatorUse {
  kStepping,     ///< the default, for every entry point: every check of checkSimulatorInputs()
  kStaticsOnly,  ///< cable_sim --statics: the time step is not judged, and step() throws
  /// Tests of the divergence handling (detection, substeps, recovery), which drive RK4 beyond its
  /// stability limit on purpose: the time step is not judged. No entry point (cable_sim, the node, the
  /// nodelet, Python) builds one.
  kUnjudgedStep,
};

/// The gate every entry point passes (cable_sim, the node, the nodelet, live tuning, Python): the rules
/// between keys and the paper model's singular springs (params/input_gate.h), and, for stepping, RK4's
/// stable step (stable_step.h). Throws ConfigError naming the key, the value and the allowed range.
void checkSimulatorInputs(const CableParams& params, const LinkProperties& properties,
                          SimulatorUse use = SimulatorUse::kStepping);

/// Steps the chain with a fixed dt and the configured time scheme. A step whose state is not finite,
/// whose mass matrix fails, whose angular velocity exceeds a limit or (RK4) whose energy balance grows by
/// more than the tolerance is discarded and retried as 2, 4, ..., kMaxSubsteps substeps; if that fails
/// too, the state stays as it was and the report says why.
class CableSimulator {
 public:
  /// The most pieces a step is split into before it counts as diverged.
  static constexpr int kMaxSubsteps = 64;
  /// The first step from a new state (a reset, setState, an equilibrium) is taken in this many pieces with
  /// RK4 (a start-up, not a retry: StepReport::substeps stays 1 and retriedSteps() does not count it).
  static constexpr int kStartupPieces = 4;

  /// Throws ConfigError (a std::invalid_argument) when checkSimulatorInputs() refuses `params` (a
  /// dt beyond RK4's reach, the paper model's azimuth or torsion springs, a broken rule between keys),
  /// and std::runtime_error when `initial.mode: equilibrium` finds no equilibrium (the message says why).
  /// `params` as the config loader gives them (or a simulator's params(): the drum's slots are built once).
  explicit CableSimulator(const CableParams& params, SimulatorUse use = SimulatorUse::kStepping);

  /// The parameters as the model uses them: the configured ones with, under a winch, the drum's slots in
  /// front (ChainModel::withDrumSlots; links, link_lengths and initial.* count every slot). What adapters
  /// size their per-link outputs by.
  const CableParams& params() const { return params_; }

  /// Back to the configured initial state and inputs at t = 0. With `initial.mode: equilibrium`, throws
  /// std::runtime_error when the statics find no equilibrium (the state is then the angles').
  void reset();
  /// Puts the cable at rest in its static equilibrium for the present inputs (current, base position,
  /// load target, deployed length), keeping the time, and restarts the energy bookkeeping. On failure
  /// the state is unchanged and the solution's message says why.
  StaticSolution resetToEquilibrium(const StaticOptions& options = {});
  /// After a divergence: the configured initial shape, at rest, under the base's present position; the
  /// time and the inputs (current, targets) carry on.
  void recover();
  /// Sets the state from paper coordinates (3n each) [rad, rad/s]; throws std::invalid_argument on a
  /// wrong size or a non-finite value.
  void setPaperState(const Eigen::VectorXd& q, const Eigen::VectorXd& qd);
  /// Restores a state saved from state() (the same cable: dynamics/state_layout.h), at the present time,
  /// with a new start for the energy bookkeeping; throws std::invalid_argument on a wrong size or a
  /// non-finite value.
  void setState(const Eigen::VectorXd& x);

  /// Live tuning: takes the fluid coefficients (`fluid.drag_normal`, `drag_tangential`, `added_mass`, and
  /// each section's, as the config loader resolved them) and the load coupling gains
  /// (`load.coupling.stiffness`, `damping`) from `params`, a re-parse of this cable's config with only
  /// those keys changed (other keys of `params` are not read), and rebuilds the chain's constants from
  /// them (simulation/tuning.cpp). Allocates: call it between steps, never within one. The state, the
  /// time, the deployment, the inputs and the energy bookkeeping carry on (none of these coefficients
  /// stores energy: drag and added mass only dissipate, the coupling's work is a work input). A new
  /// coupling stiffness is bumpless: the spring's force stays as it was at the step and its rest point's
  /// shift bleeds off in a few seconds (EndConditions::shiftCouplingRest). Throws
  /// std::invalid_argument, changing nothing, when `params` has another number of links or sections, or
  /// (RK4) when the new coefficients need a step below simulation.dt (checkSimulatorInputs: ConfigError
  /// naming it and the mode).
  void retune(const CableParams& params);

  /// Advances by one time step dt.
  StepReport step();

  double time() const { return time_; }
  double dt() const { return dt_; }
  int links() const { return dynamics_.links(); }
  /// Per-link constants of this cable (derived once from the parameters).
  const LinkProperties& properties() const { return dynamics_.properties(); }
  /// The state x (dynamics/state_layout.h) and the equations that step it: for tests and benchmarks.
  const Eigen::VectorXd& state() const { return x_; }
  ChainDynamics& dynamics() { return dynamics_; }

  /// The paper coordinates (3n) [rad] and their rates (3n) [rad/s] of the present state.
  void paperCoordinates(Eigen::VectorXd& q, Eigen::VectorXd& qd) const { dynamics_.paperCoordinates(x_, q, qd); }

  /// The winch (docs/MODEL.md section 8): commands take effect from the next step, within the limits.
  bool hasWinch() const { return ends_.hasWinch(); }
  const Winch& winch() const { return ends_.winch(); }
  /// Pay out (> 0) or haul in (< 0) [m/s]; replaces a target length and the configured schedule (its
  /// commands still to come are dropped; reset() starts it again).
  /// Throws std::invalid_argument (params/input_gate.h) without a winch or beyond +-winch.max_speed.
  void commandWinchSpeed(double speed);
  /// Drive to a deployed length [m] and stop there; replaces the schedule as commandWinchSpeed() does.
  /// Throws std::invalid_argument without a winch or
  /// outside [winch.min_length, winch.max_length].
  void commandWinchLength(double length);
  /// The base link's slot (0 without a winch) and the deployed length [m].
  int firstLink() const { return dynamics_.deployed().firstLink(); }
  double deployedLength() const;
  /// Links added and removed at the winch since reset, and the mechanical energy those changes took
  /// out (counted as dissipated: the kink lost when two links merge) [J].
  long linksAdded() const { return links_added_; }
  long linksRemoved() const { return links_removed_; }
  double regridEnergy() const { return regrid_energy_; }

  /// Current outputs (evaluates the dynamics at the present state).
  void snapshot(SimulationSnapshot& out);

  // Inputs, all in one frame: world axes (REP-103, z up) with the origin at the base's rest position,
  // the frame of the config's motion offsets and current.

  // Each setter checks its value in the gate (params/input_gate.h) and throws std::invalid_argument,
  // changing nothing, when it is refused.

  /// Uniform current [m/s], replacing the configured field until reset(); fluid.current's range.
  void setCurrent(const Eigen::Vector3d& current);
  /// External target for the load (modes anchored/attached) [m], [m/s]: the ROV's attachment point at
  /// simulated time `at` [s] (NaN: now), with the ROV's attitude (world from ROV) for the wrench on it;
  /// replaces the configured motion until reset(). Between targets the point moves on with `velocity`
  /// (EndConditions::setLoadTarget). Positions within +-kMaxInputPosition, speeds up to
  /// kMaxInputSpeed, a unit attitude.
  void setLoadTarget(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity,
                     const Eigen::Quaterniond& attitude = Eigen::Quaterniond::Identity(),
                     double at = std::numeric_limits<double>::quiet_NaN());
  /// External base position and velocity [m], [m/s]: the vessel's hang-off point, with the vessel's
  /// attitude for the wrench on it; replaces the configured motion until reset().
  void setBaseTarget(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity,
                     const Eigen::Quaterniond& attitude = Eigen::Quaterniond::Identity());

  // The ROV body (load.mode body). Each setter throws std::invalid_argument without a body or on a
  // refused value (the gate's message).

  /// true when the load is an ROV body simulated here.
  bool hasBody() const { return dynamics_.model().body().active; }
  /// The commanded thrust at the body's origin, body frame [N], [N m] (what a thruster allocator gives),
  /// held until the next call or reset(); the station keeper's wrench adds to it.
  void setBodyThrust(const Eigen::Vector3d& force, const Eigen::Vector3d& torque);
  /// The station keeper's target: the body's origin (world axes) [m] and attitude (world from body);
  /// the body's pose at reset until set.
  void setBodyTarget(const Eigen::Vector3d& position, const Eigen::Quaterniond& attitude);
  /// The body's pose and twist now (world axes; angular velocity in the body frame).
  BodyPose bodyPose();

  /// How far the energy balance has drifted since reset (schemes that balance energy: RK4), as a
  /// fraction of the largest mechanical energy scale seen [-]; an unstable mode that the per-step
  /// check lets through a little at a time shows here. Negative when not measured (semi-implicit).
  /// Restarts from the present balance when an external base target moves the base (a jump in
  /// potential energy that no work term records), keeping the largest drift so far.
  double energyDrift() const { return scheme_->balancesEnergy() ? energy_drift_ : -1.0; }
  /// How far the energy balance has risen since reset, at any step, as a fraction of the largest mechanical
  /// energy scale seen [-], for schemes whose steps are not judged by it (the implicit one: its balance may
  /// fall with its numerical damping, but a rise is energy its steps put in); -1 for RK4 (energyDrift()).
  /// Restarts with the drift's reference (an external base target), keeping the largest rise so far.
  double energyRise() const { return scheme_->balancesEnergy() ? -1.0 : energy_rise_; }
  /// Steps since reset that needed substeps.
  long retriedSteps() const { return retried_steps_; }
  /// The next step taken on a copy of this simulator (this one unchanged): whether the present state can be
  /// stepped at all, and why not (a reset's check before the state is used). Allocates the copy.
  StepReport trialStep() const {
    CableSimulator probe(*this);
    return probe.step();
  }
  /// Axial elasticity (0 with rigid links): the largest tension a link's stretch has carried at a step's
  /// end since the last reset [N], and the snaps since then: a link shorter than unstretched by more than
  /// 0.1 % of its length (slack) that comes taut (s >= 0), judged at the steps' ends.
  double largestTension() const { return largest_tension_; }
  long snaps() const { return snaps_; }

  /// The recommended RK4 time step: half the stability limit estimated from the stiffest mode [s]
  /// (stable_step.h; a dt up to the limit itself is accepted).
  double estimateStableTimeStep() const { return estimateStableStep(params_, properties()).recommended; }

 private:
  /// Fills out.port from the evaluation `out` holds at the inputs `ends`.
  void couplingPort(const EndInputs& ends, SimulationSnapshot& out) const;
  /// One piece of a step, of length h: the scheme's advance, the projection of the axes, the judgement.
  bool advance(double h);
  /// Whether the balance from `before` to `after` rose by at most `tolerance` of its scale; records the
  /// refusal otherwise.
  bool acceptEnergy(const EnergyBalance& before, const EnergyBalance& after, double tolerance);
  /// Why advance() last refused a step (a verdict of step_check.h, or the check that failed; static text,
  /// no allocation in the step), for the message of a step that diverged even in substeps; with "energy
  /// created", the energy it created [J], the scale it was judged against [J] and the tolerance.
  const char* refusal_ = "";
  double refused_energy_ = 0.0, refused_scale_ = 0.0, refused_tolerance_ = 0.0;
  /// The energy balance at the present state and time, evaluated afresh.
  EnergyBalance balanceNow();
  /// A new state: the balance's references, the URDF's frame hints and the scheme's reused stage are
  /// forgotten, and the next step is a start-up (kStartupPieces).
  void startAfresh();
  /// The configured deployment: the drum's slots stowed, the winch at the configured length.
  void deployConfigured();
  /// After an accepted step: the winch moves on and adds or removes a link when its link leaves its band.
  void finishWinchStep();
  /// The coupling's integral action after an accepted step (EndConditions::integrateCouplingRest), at the
  /// kinematics the step left.
  void integrateCouplingRest();
  /// resetToEquilibrium with the coupling's integral action: at most this many more statics solves, to put
  /// the tip within this distance of the target [m].
  static constexpr int kIntegralStaticsPasses = 8;
  static constexpr double kIntegralStaticsTolerance = 1e-6;
  /// Before a step: the body's thrust, commanded plus the station keeper's at the present pose.
  void updateBodyThrust();

  CableParams params_;
  SimulatorUse use_;
  ChainDynamics dynamics_;
  SchemeHolder scheme_;  ///< copied by clone(): a copy of the simulator is a trial of it
  EndConditions ends_;
  StepLimits limits_;
  double dt_;                           ///< [s]
  double time_ = 0.0;                   ///< [s]
  bool start_balance_known_ = false;    ///< start_balance_ is the present state's (nothing changed since)
  EnergyBalance start_balance_;
  // Drift of the balance since reset (energyDrift()).
  bool drift_reference_known_ = false;
  /// Keeps the URDF's azimuth continuous from one snapshot to the next where the elevation is 0
  /// (linkFrames); zeroed by a new state. `levers_`: each link's base end to far end, the snapshot's scratch [m].
  Eigen::VectorXd alpha_hint_, levers_;
  double drift_reference_ = 0.0;        ///< the balance the drift is measured from [J]
  double largest_scale_ = 0.0;          ///< the largest mechanical magnitude seen [J]
  double energy_drift_ = 0.0;           ///< [-]
  double energy_rise_ = 0.0;            ///< [-], schemes not judged by the balance
  long retried_steps_ = 0;
  int startup_pieces_ = kStartupPieces;  ///< pieces of the next step if it is the first from a new state
  double largest_tension_ = 0.0;  ///< [N]
  long snaps_ = 0;
  std::vector<char> slack_;  ///< (n) each link slack at the last step's end (axial elasticity)
  /// After an accepted step (axial elasticity): the largest tension and the snaps (no allocation).
  void watchStretches(bool count_snaps);
  long links_added_ = 0, links_removed_ = 0;
  double regrid_energy_ = 0.0;          ///< [J]
  Eigen::VectorXd x_, x_start_;         ///< (StateLayout::size(n)) the state, and at the step's start
  Eigen::VectorXd q_, qd_;              ///< (3n) for messages
  // The ROV body: commanded thrust (body frame) [N, N m], the station keeper's target (world) and the
  // thrust applied in the last step.
  Eigen::Matrix<double, 6, 1> commanded_thrust_ = Eigen::Matrix<double, 6, 1>::Zero();
  Eigen::Matrix<double, 6, 1> applied_thrust_ = Eigen::Matrix<double, 6, 1>::Zero();
  Eigen::Vector3d body_target_position_ = Eigen::Vector3d::Zero();
  Eigen::Quaterniond body_target_attitude_ = Eigen::Quaterniond::Identity();
  Eigen::Vector3d keeper_integral_ = Eigen::Vector3d::Zero();  ///< the station keeper's position integral [m s]
};

}  // namespace cable_dynamics
