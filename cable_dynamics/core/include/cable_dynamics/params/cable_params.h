#pragma once
/// \file
/// \brief Immutable, validated parameters of the cable model (SI units) and the per-link quantities
///        derived from them. ROS-free: Eigen and std only.

#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/StdVector>

namespace cable_dynamics {

/// How the joint springs are written.
enum class StiffnessModel {
  kPaper,    ///< the paper's K = diag(K_e, K_a, K_t) acting on the generalized coordinates directly
  kBending,  ///< energy from the relative bend angle and parallel-transport twist between neighbours
};

/// Time-stepping scheme (simulation/integrators/).
enum class Integrator {
  kRk4,           ///< classical fourth-order Runge-Kutta, explicit
  kSemiImplicit,  ///< linearized backward Euler in the angular velocities
  kImplicit,      ///< linearly implicit ROS2 step, O(n): stiff terms in the articulated-body recursion
};

/// How the equations of motion are solved for the accelerations (dynamics/).
enum class Formulation {
  kRecursive,  ///< the O(n) articulated-body recursion
  kPaper,      ///< the dense 3n x 3n mass matrix generated element by element as in the paper, O(n^3)
};

/// Config spelling of each enum value ("rk4", "semi_implicit", "recursive", "paper", ...).
const char* integratorName(Integrator integrator);
const char* formulationName(Formulation formulation);

/// How the base holds the first link (the bending model's joint 1).
enum class BaseFixity {
  kClamped,  ///< along base.direction: joint 1's springs act against the clamp
  kPinned,   ///< free to rotate: no spring or damper at joint 1
};

/// How an anchored or attached tip holds the last link (the bending model).
enum class TipFixity {
  kPinned,   ///< free to rotate: the coupling holds a point
  kClamped,  ///< its direction held along load.direction by a bend spring (a swivel: torsion is free)
};

/// How an anchored tip holds its point (load.anchor).
enum class AnchorHold {
  /// Exactly: a constraint force keeps the tip on the anchor (docs/MODEL.md section 14); load.coupling
  /// is not used. The recursive formulation's RK4 solves for it in the recursion; the implicit and
  /// semi-implicit steps fold a stiff internal hold into their matrix instead.
  kExact,
  kSpring,  ///< by the PD coupling load.coupling: an anchor that gives (a drag anchor, a soft mooring)
};

/// How the terminal load is held (used by the simulator).
enum class LoadMode {
  kFree,      ///< the load hangs at the tip, moved only by the cable and the fluid
  kAnchored,  ///< the load is held at a fixed point (seabed) by PD constraint forces
  kAttached,  ///< the load follows an external pose (the ROV) through a stiff PD coupling
  kBody,      ///< the load is an ROV body simulated here (6 DOF, Fossen's form), hung on the tip at load.attachment
};

/// Spring constants per direction for every joint [N m/rad], or rigidities from which they are derived.
struct StiffnessParams {
  StiffnessModel model = StiffnessModel::kPaper;
  double elevation = 0.0;  ///< [N m/rad]
  double azimuth = 0.0;    ///< [N m/rad]
  double torsion = 0.0;    ///< [N m/rad]
  /// Bending rigidity EI [N m^2]; when > 0, elevation = azimuth = EI / s_k for joint k, s_k =
  /// (l_{k-1} + l_k)/2 between link centres and l_1/2 from the clamp (cable_params.cpp).
  double bending_rigidity = 0.0;
  /// Torsional rigidity GJ [N m^2]; when > 0, torsion = GJ / s_k (the same s_k).
  double torsional_rigidity = 0.0;
};

/// Viscous joint damping per direction [N m s/rad].
struct DampingParams {
  double elevation = 0.0;
  double azimuth = 0.0;
  double torsion = 0.0;
};

/// A prescribed motion: offset + amplitude sin(2 pi t / period + phase) + velocity t, world frame (z up).
struct MotionParams {
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();     ///< [m]
  Eigen::Vector3d amplitude = Eigen::Vector3d::Zero();  ///< [m]
  double period = 10.0;                                 ///< [s]
  double phase = 0.0;                                   ///< [rad]; pi/2 starts at rest
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();   ///< [m/s]
  /// Roll, pitch and yaw (R = Rz(yaw) Ry(pitch) Rx(roll)), each amplitude sin(2 pi t / period + phase)
  /// [rad]: they move the body's points off its origin (the hang-off point, the attachment).
  Eigen::Vector3d attitude_amplitude = Eigen::Vector3d::Zero();
  Eigen::Vector3d attitude_phase = Eigen::Vector3d::Zero();  ///< [rad]
};

/// The ROV of load.mode body: a rigid body in Fossen's form (Handbook of Marine Craft Hydrodynamics and
/// Motion Control, 2011, ch. 6-7), in its own frame (x forward, y left, z up: REP-103) about its origin O.
/// Its mass and displaced volume are load.mass and load.volume.
struct RovBodyParams {
  /// Rigid-body inertia about the centre of gravity, body frame [kg m^2]: symmetric positive definite.
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Identity();
  /// Added mass about O, body frame, rows and columns (surge, sway, heave, roll, pitch, yaw) [kg, kg m,
  /// kg m^2]: symmetric positive semi-definite (the hydrodynamic derivatives' minus: M_A = -[X_u' ...]).
  Eigen::Matrix<double, 6, 6> added_mass = Eigen::Matrix<double, 6, 6>::Zero();
  /// Linear and quadratic damping per axis, on the velocity relative to the water [N s/m, N m s/rad] and
  /// [N s^2/m^2, N m s^2/rad^2]: the force is -(d_l + d_q |nu_r|) nu_r on each of the six axes, >= 0.
  Eigen::Matrix<double, 6, 1> linear_damping = Eigen::Matrix<double, 6, 1>::Zero();
  Eigen::Matrix<double, 6, 1> quadratic_damping = Eigen::Matrix<double, 6, 1>::Zero();
  Eigen::Vector3d center_of_gravity = Eigen::Vector3d::Zero();   ///< from O, body frame [m]
  Eigen::Vector3d center_of_buoyancy = Eigen::Vector3d::Zero();  ///< from O, body frame [m]
  /// Attitude at start and after a reset: roll, pitch, yaw (world from body, R = Rz(yaw) Ry(pitch) Rx(roll)) [rad].
  Eigen::Vector3d initial_attitude = Eigen::Vector3d::Zero();
  /// The built-in station keeper (simulation/station_keeper.h): a PID law on the position error and a PD
  /// law on the attitude error towards the start pose (or a target set later), its wrench added to the
  /// commanded thrust. Off when all gains are 0.
  Eigen::Vector3d position_gain = Eigen::Vector3d::Zero();  ///< world x, y, z [N/m]
  Eigen::Vector3d velocity_gain = Eigen::Vector3d::Zero();  ///< world x, y, z [N s/m]
  Eigen::Vector3d integral_gain = Eigen::Vector3d::Zero();  ///< world x, y, z, on the position error's integral [N/(m s)]
  Eigen::Vector3d attitude_gain = Eigen::Vector3d::Zero();  ///< body roll, pitch, yaw [N m/rad]
  Eigen::Vector3d rate_gain = Eigen::Vector3d::Zero();      ///< body roll, pitch, yaw [N m s/rad]
  double max_force = 1e300;   ///< the station keeper's force saturates at this norm [N]
  double max_torque = 1e300;  ///< and its torque at this norm [N m]
};

/// The terminal load (ROV, clump weight or nothing).
struct LoadParams {
  double mass = 0.0;    ///< [kg], 0 = bare cable
  double volume = 0.0;  ///< displaced volume [m^3], gives buoyancy
  LoadMode mode = LoadMode::kFree;
  double drag_area = 0.0;            ///< frontal area times drag coefficient, C_d A [m^2]
  double added_mass = 0.0;           ///< added mass of the load [kg]
  AnchorHold anchor = AnchorHold::kExact;  ///< mode anchored: held exactly, or by the coupling spring
  double coupling_stiffness = 2.0e4; ///< PD coupling to the anchor (load.anchor spring) / ROV [N/m]
  double coupling_damping = 2.0e3;   ///< [N s/m]
  /// The coupling's integral action [s], 0 = none: the spring's rest point moves by -(tip - target) / T_i a
  /// second, so that at rest the tip sits on the target and the spring is preloaded with the tension (a soft
  /// coupling then passes the force the cable has at the ROV's own point; EndConditions::integrateCouplingRest).
  double coupling_integral_time = 0.0;
  /// Anchor / ROV target relative to the load's initial position (modes anchored, attached).
  MotionParams motion;
  /// Where the tether enters the ROV, in the ROV's frame (x forward, z up at rest) [m]: the target the
  /// tip is coupled to is this point of the ROV, and the cable's force there puts a moment on it.
  Eigen::Vector3d attachment = Eigen::Vector3d::Zero();
  /// Pinned, or clamped along `direction` (anchored: world frame; attached: the ROV's frame, turning
  /// with it): the last link's axis, from the cable into the tip, held by a bend spring EI / (l_n / 2)
  /// (the half link to the tip, as at the base) and the bend damper. Torsion stays free (a swivel).
  TipFixity fixity = TipFixity::kPinned;
  Eigen::Vector3d direction = -Eigen::Vector3d::UnitZ();  ///< unit [-]
  RovBodyParams body;  ///< mode body only
  /// The anchor holds its point exactly (mode anchored with load.anchor exact).
  bool heldExactly() const { return mode == LoadMode::kAnchored && anchor == AnchorHold::kExact; }
};

/// The cable's base (vessel, cage or fixed point).
struct BaseParams {
  MotionParams motion;  ///< prescribed motion of the vessel relative to its initial pose
  /// The hang-off point (A-frame sheave, moonpool) in the vessel's frame, from the vessel's origin [m]:
  /// the base of the cable, which the vessel's attitude moves on an arc.
  Eigen::Vector3d hang_off = Eigen::Vector3d::Zero();
  /// How the base holds link 1 (bending model): clamped along `direction` (joint 1's bend and twist
  /// springs and dampers act against the clamp), or pinned (free to rotate: joint 1 has none).
  BaseFixity fixity = BaseFixity::kClamped;
  /// Clamp direction, world frame (z up), unit [-]: straight down by default; an I-tube or a bend
  /// stiffener angle otherwise.
  Eigen::Vector3d direction = -Eigen::Vector3d::UnitZ();
};

/// The surrounding fluid.
struct FluidParams {
  double density = 1025.0;          ///< [kg/m^3]; 0 = in air
  double drag_normal = 1.2;         ///< Morison drag coefficient normal to a link [-]
  double drag_tangential = 0.01;    ///< skin-friction drag coefficient along a link [-]
  double added_mass = 1.0;          ///< added-mass coefficient normal to a link [-]
  Eigen::Vector3d current = Eigen::Vector3d::Zero();  ///< uniform current, world frame (z up) [m/s]
  /// Optional depth profile: rows (depth below the base [m], current x, y, z world frame [m/s]), depth
  /// increasing; linear in between, constant beyond the ends. Replaces `current` when given.
  std::vector<Eigen::Vector4d, Eigen::aligned_allocator<Eigen::Vector4d>> current_profile;
  int drag_points = 3;  ///< Gauss-Legendre points per link for the distributed drag
};

/// Where a run starts from.
enum class InitialMode {
  kAngles,       ///< the configured paper angles, at rest
  kEquilibrium,  ///< the static equilibrium for the configured loads and ends (statics/static_solver.h)
};

/// Initial state in the paper's coordinates, one value per joint [rad].
struct InitialState {
  /// kEquilibrium solves from the angles' shape: an anchored or attached load's target is relative to
  /// the tip of that shape, as with kAngles.
  InitialMode mode = InitialMode::kAngles;
  std::vector<double> elevation;
  std::vector<double> azimuth;
  std::vector<double> torsion;
};

/// Time stepping.
struct SimulationParams {
  double dt = 0.001;                                   ///< [s]
  Integrator integrator = Integrator::kRk4;
  /// The implicit integrator's spectral radius at infinite h omega, in [0, 1] (second order at every value):
  /// 1 damps nothing (the trapezoidal rule on linear problems), below 1 the modes with h omega >> 1 lose
  /// 1 - rho_inf per step while those at h omega <= 0.25 keep 0.9997 of their amplitude per period
  /// (linear_implicit.h). 0.9 by default: an undamped stiff cable released kinked stays stable with it.
  double rho_infinity = 0.9;
  /// Same physics either way (docs/MODEL.md section 4).
  Formulation formulation = Formulation::kRecursive;
  double duration = 10.0;          ///< default length of an offline run (cable_sim without --duration) [s]
};

/// One entry of a winch schedule (cable_sim): from `time` on, run at `speed` (pay out > 0, haul in < 0)
/// or drive to the deployed length `length` within the winch's limits.
struct WinchCommand {
  double time = 0.0;       ///< [s]
  bool to_length = false;  ///< false: `value` is a speed [m/s]; true: a target length [m]
  double value = 0.0;
};

/// A winch at the base that pays the cable out and hauls it in (docs/MODEL.md section 8). The cable
/// starts deployed as configured (cable.length); links are added and removed at the base as the
/// deployed length passes whole links of the base link's configured length.
struct WinchParams {
  bool enabled = false;
  double min_length = 0.0;        ///< [m], at least one link
  double max_length = 0.0;        ///< [m], sizes every workspace at start
  double max_speed = 1.0;         ///< [m/s]
  double max_acceleration = 0.5;  ///< [m/s^2]
  double speed = 0.0;             ///< commanded speed at start [m/s]
  std::vector<WinchCommand> schedule;  ///< time-ordered commands (offline runs)
  /// The slots the drum needs for the longest deployment, in front of the configured cable.links: the
  /// config loader counts them (drumSlotsFor; the gate refuses more than ranges::kLinks in all); the model
  /// puts them in front of the configured cable (ChainModel::withDrumSlots), which marks it in `slots_built`.
  int stored_links = 0;
  /// true in the model's copy of the parameters, where links, link_lengths and initial.* count the drum's
  /// slots too (CableSimulator::params()); false as the config loader gives them: the configured cable.
  bool slots_built = false;
  double link_length = 0.0;       ///< length of a link added at the winch [m] (the base link's configured length)
};

/// The slots the drum needs (WinchParams::stored_links) for the longest deployment w.max_length from the
/// configured `deployed` length [m], in links of w.link_length: one more than the whole links it adds,
/// since the winch's link is between one and 2.25 links long.
int drumSlotsFor(const WinchParams& w, double deployed);

/// One section of the cable (`cable.sections`): a stretch of `length` along the configured cable, counted
/// from its base, with properties of its own. The loader fills every field (a key left out takes the
/// cable's value). A link takes the properties of the section its centre lies in (docs/MODEL.md section 9).
struct SectionParams {
  double length = 0.0;              ///< [m]
  double diameter = 0.025;          ///< outer diameter [m]
  double mass_per_length = 0.6;     ///< in air [kg/m]
  double bending_rigidity = 0.0;    ///< EI [N m^2] (used when the cable's springs come from rigidities)
  double torsional_rigidity = 0.0;  ///< GJ [N m^2]
  double axial_stiffness = 0.0;     ///< EA [N]; 0: the cable's (cable.axial_stiffness)
  double drag_normal = 1.2;         ///< Morison C_n [-]
  double drag_tangential = 0.01;    ///< skin friction C_t [-]
  double added_mass = 1.0;          ///< added-mass coefficient C_a normal to the cable [-]
  /// The section's minimum bend radius [m] (`cable.sections[i].limits.min_bend_radius`); 0: no bend limit.
  /// Left out: the cable's (`cable.limits.min_bend_radius`).
  double min_bend_radius = 0.0;
};

/// The engineering limits a design is checked against (`cable.limits`, docs/MODEL.md section 13). An
/// absent limit is 0 (or has_min_seabed_clearance false) and contributes nothing to the utilisation.
struct LimitParams {
  double max_tension = 0.0;      ///< the safe working load [N]; 0: no tension limit
  double min_bend_radius = 0.0;  ///< the cable's minimum bend radius [m] (sections may override); 0: none
  /// The smallest height above the seabed a suspended link end may have [m] (needs a seabed).
  bool has_min_seabed_clearance = false;
  double min_seabed_clearance = 0.0;
};

/// A point attachment (`attachments`): a buoyancy module (float), a clump weight, a sensor, at arc length
/// `arc_length` from the base of the configured cable. Its submerged weight, drag and mass act at that
/// point of the link that holds it (docs/MODEL.md section 9).
struct AttachmentParams {
  double arc_length = 0.0;  ///< [m] from the base of the configured cable
  double mass = 0.0;        ///< in air [kg]
  double volume = 0.0;      ///< displaced volume [m^3]; volume > mass / rho floats
  double drag_area = 0.0;   ///< C_d A [m^2], isotropic: 1/2 rho C_d A |v| v with the point's relative velocity
  double added_mass = 0.0;  ///< isotropic added mass [kg]
};

/// Bathymetry on a regular grid (`seabed.grid` or `seabed.grid_file`): the seabed's depth below the
/// base's rest position [m] (positive down) at world (x0 + i dx, y0 + j dy), bilinear in between and
/// constant beyond the grid's edges.
struct SeabedGrid {
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();   ///< world x, y of depth(0, 0) [m]
  Eigen::Vector2d spacing = Eigen::Vector2d::Ones();  ///< dx, dy > 0 [m]
  Eigen::MatrixXd depth;  ///< (rows = y points, cols = x points, at least 2 x 2) [m]
};

/// The seabed (docs/MODEL.md section 12): a flat bottom at `depth`, or bathymetry on a grid; a normal
/// spring-damper per unit length at points along each link, and regularized Coulomb friction.
struct SeabedParams {
  bool enabled = false;
  double depth = 0.0;  ///< flat seabed: depth below the base's rest position [m] (world z = -depth)
  bool has_grid = false;
  SeabedGrid grid;     ///< replaces `depth` when has_grid
  /// Allowed penetration [m]: the default stiffness lets the heaviest section rest at 1 % of it,
  /// leaving the rest for dynamics (landing, a tension pulling the cable down). Default: half the
  /// largest diameter.
  double penetration = 0.0;
  /// Normal stiffness per unit length [N/m^2]; 0 = 100 w'_max / penetration, w'_max the heaviest
  /// submerged weight per length of the cable's sections [N/m].
  double stiffness = 0.0;
  double damping_ratio = 0.5;      ///< of each link's normal mode on the spring, m' + m_a' per length [-]
  double friction_axial = 0.0;     ///< Coulomb coefficient along the cable [-]
  double friction_lateral = 0.0;   ///< across it [-]
  double friction_velocity = 0.01; ///< regularization: the anchor's damper mu N / v_r; without anchors viscous below it [m/s]
  /// Static friction: how far a point moves from its anchor on the bed before it slides, x_b [m]; 0: none
  /// (regularized Coulomb, which creeps on a slope). Default 5 mm.
  double friction_breakout = 0.005;
  int contact_points = 4;          ///< points per link at which the contact is evaluated (midpoint rule)
};

/// Every parameter of one cable; SI units. The config loader fills and checks it; filled in by hand, the
/// simulator checks it against the same ranges before it uses it (checkConfigRanges, params/input_gate.h).
struct CableParams {
  /// n, number of rigid links as configured (cable.links). In the model's copy with a winch
  /// (winch.slots_built: ChainModel::withDrumSlots), every slot the longest deployment needs, the first
  /// winch.stored_links of them on the drum at start; so also link_lengths and initial.*.
  int links = 1;
  std::vector<double> link_lengths;       ///< (n) [m]; slots on the drum: the length they will have
  WinchParams winch;
  double diameter = 0.025;                ///< outer diameter [m]
  double mass_per_length = 0.6;           ///< in air [kg/m]
  /// Axial stiffness EA [N]: 0 (the default) keeps the links rigid (inextensible); > 0 gives each link a
  /// stretch along its axis (docs/MODEL.md section 12).
  double axial_stiffness = 0.0;
  /// Internal axial damping [N s]: the damper's force is axial_damping times the strain rate (as
  /// MoorDyn's BA), acting only while the link is taut; 0 by default.
  double axial_damping = 0.0;
  /// Sections along the configured cable from its base (empty: one uniform cable of the values above).
  /// Their lengths add up to the configured cable's length. With a winch the drum's slots take the
  /// first (base) section's properties.
  std::vector<SectionParams> sections;
  std::vector<AttachmentParams> attachments;  ///< point attachments, by arc length
  LimitParams limits;                         ///< safe working load, minimum bend radius, seabed clearance
  StiffnessParams stiffness;
  DampingParams damping;
  LoadParams load;
  BaseParams base;
  FluidParams fluid;
  double gravity = 9.81;                  ///< [m/s^2]
  SeabedParams seabed;
  InitialState initial;
  SimulationParams simulation;

  /// Total length of every link [m] (with the drum's slots built: of every slot, the longest deployment).
  double totalLength() const;
  /// Deployed length at start [m] (totalLength() without a winch).
  double deployedLength() const;
  /// The slots on the winch's drum at start, [0, drumSlots()) (0 without a winch): where the configured
  /// deployment's base link is. Adapters read this, never winch.stored_links.
  int drumSlots() const { return winch.enabled && winch.slots_built ? winch.stored_links : 0; }
  /// true when the links stretch: cable.axial_stiffness or a section's is > 0.
  bool stretches() const;
};

/// An attachment placed on its link (LinkProperties::attachments).
struct LinkAttachment {
  int link = 0;                 ///< 0-based slot that holds it
  double offset = 0.0;          ///< distance from that link's base end [m], in [0, l]
  double mass = 0.0;            ///< in air [kg]
  double submerged_mass = 0.0;  ///< mass - rho V [kg] (negative: a float)
  double added_mass = 0.0;      ///< isotropic [kg]
  double drag_area = 0.0;       ///< C_d A [m^2]
};

/// Quantities derived per link from CableParams; vectors have size n, index k-1 for link k. The mass,
/// inertias and submerged mass are the cable's own (its section's); the attachments are listed apart.
struct LinkProperties {
  int n = 0;
  Eigen::VectorXd radius;              ///< (n) outer radius of the link's section [m]
  Eigen::VectorXd length;              ///< (n) [m]
  Eigen::VectorXd mass;                ///< (n) in air [kg]
  Eigen::VectorXd inertia_transverse;  ///< (n) about the CoM, solid cylinder m(l^2/12 + r^2/4) [kg m^2]
  Eigen::VectorXd inertia_polar;       ///< (n) about the link axis, solid cylinder m r^2/2 [kg m^2]
  Eigen::VectorXd submerged_mass;      ///< (n) mass minus displaced water, pi r^2 l rho [kg]
  Eigen::VectorXd added_mass_per_length;  ///< (n) normal added mass per length, C_a rho pi r^2 [kg/m]
  Eigen::VectorXd drag_normal;         ///< (n) Morison C_n of the link's section [-]
  Eigen::VectorXd drag_tangential;     ///< (n) skin friction C_t [-]
  Eigen::VectorXd axial_stiffness;     ///< (n) EA of the link's section [N]; all 0: rigid links
  double axial_damping = 0.0;          ///< internal axial damping [N s] (force per strain rate)
  Eigen::VectorXi section;             ///< (n) 0-based index of the link's section (0 without sections)
  /// (n) the minimum bend radius of the link's section [m]; 0: no bend limit (docs/MODEL.md section 13)
  Eigen::VectorXd min_bend_radius;
  double max_tension = 0.0;            ///< safe working load [N]; 0: no tension limit
  double min_seabed_clearance = -1.0;  ///< [m]; < 0: no clearance limit
  std::vector<LinkAttachment> attachments;  ///< by link, in the order of arc length
  Eigen::VectorXd stiffness_elevation; ///< (n) per joint [N m/rad]
  Eigen::VectorXd stiffness_azimuth;   ///< (n) [N m/rad]
  Eigen::VectorXd stiffness_torsion;   ///< (n) [N m/rad]
  Eigen::VectorXd damping_elevation;   ///< (n) [N m s/rad]
  Eigen::VectorXd damping_azimuth;     ///< (n) [N m s/rad]
  Eigen::VectorXd damping_torsion;     ///< (n) [N m s/rad]
  double load_mass = 0.0;              ///< [kg]
  double load_submerged_mass = 0.0;    ///< [kg]
  double gravity = 9.81;               ///< [m/s^2]
  StiffnessModel stiffness_model = StiffnessModel::kPaper;
  /// The base clamp's axis in the paper frame (z down), unit [-], and its twist about the vertical,
  /// sigma = psi of the clamp direction [rad]: joint 1 of the bending model bends and twists link 1
  /// against this frame. (A pinned base has no springs or dampers at joint 1 instead.)
  Eigen::Vector3d clamp_axis = Eigen::Vector3d::UnitZ();
  double clamp_twist = 0.0;
  /// The bend radius's ends (docs/MODEL.md section 13): the bending model with base.fixity clamped bends
  /// link 1 against clamp_axis (joint 1 has a radius), and load.fixity clamped the last link against the
  /// tip's clamp; otherwise the ends are free hinges (no bend there).
  bool clamped_base = false;
  bool clamped_tip = false;
  /// A clamped tip (LoadParams::fixity): the bend spring [N m/rad] and damper [N m s/rad] between the
  /// last link and the tip's clamp, and the clamp's axis at rest, paper frame (an attached ROV turns it).
  double tip_clamp_stiffness = 0.0;
  double tip_clamp_damping = 0.0;
  Eigen::Vector3d tip_clamp_axis = Eigen::Vector3d::UnitZ();
};

/// Derives the per-link quantities; `params` must already be valid (see config_loader.h).
LinkProperties deriveLinkProperties(const CableParams& params);

/// Name of generalized coordinate `index` (0-based): "joint_K_elevation|azimuth|torsion", K = index/3 + 1.
std::string coordinateName(int index);

/// Names of all 3n coordinates, in the order of q.
std::vector<std::string> coordinateNames(int links);

}  // namespace cable_dynamics
