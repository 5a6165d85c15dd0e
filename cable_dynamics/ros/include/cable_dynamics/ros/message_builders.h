#pragma once
/// \file
/// \brief The node's output messages, allocated once (prepareOutputs) and then only filled, by index, from
///        an OutputSource. These functions call nothing on the simulator and change no state.

#include <string>
#include <vector>

#include <cable_msgs/CableState.h>
#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/WrenchStamped.h>
#include <sensor_msgs/JointState.h>
#include <visualization_msgs/MarkerArray.h>

#include "cable_dynamics/params/cable_params.h"
#include "cable_dynamics/ros/output_source.h"
#include "cable_dynamics/ros/scene_markers.h"
#include "cable_dynamics/urdf/cable_urdf.h"

namespace cable_dynamics {

/// Every message the node publishes, preallocated for every slot. With a winch the joint states, the link
/// frames and the cable's line carry the deployed slots [first_link, n) only (shapeOutputs); cable_state's
/// tension keeps one entry per slot (0 on the drum).
struct CableOutputs {
  sensor_msgs::JointState joints;                           ///< 3 per deployed link, slot order
  std::vector<geometry_msgs::TransformStamped> transforms;  ///< world -> paper, 3 per deployed link, the load
  /// cable (line), load, base_force, load_force, tension_scale, the vessel's and the ROV's shapes, then
  /// cable_tube: one cylinder per slot (scene_markers.h)
  visualization_msgs::MarkerArray markers;
  cable_msgs::CableState state;
  /// The cable's force on the ROV and its moment about the ROV's origin, in the ROV's frame (rov_wrench);
  /// the force alone at the load, in world axes (rov_wrench_world).
  geometry_msgs::WrenchStamped wrench, wrench_world;
  /// The cable's force on the vessel at the hang-off point and its moment about the vessel's origin,
  /// in the vessel's frame (base_wrench) and in world axes (base_wrench_world).
  geometry_msgs::WrenchStamped base_wrench, base_wrench_world;
  /// world -> vessel and world -> rov: the bodies' frames, which the wrenches above refer to.
  std::vector<geometry_msgs::TransformStamped> body_transforms;
  diagnostic_msgs::DiagnosticArray diagnostics;
  // The shape: which slots the messages above carry, and the named entries of the drum's slots, kept
  // aside (moved, never copied: no allocation) until their links are paid out.
  int slots = 0;       ///< n, every slot
  int first_link = 0;  ///< the messages carry slots [first_link, n)
  std::vector<std::string> stowed_joint_names;                     ///< slots [0, first_link), 3 each, slot order
  std::vector<geometry_msgs::TransformStamped> stowed_transforms;  ///< slots [0, first_link), 3 each, slot order
};

/// The winch as /diagnostics reports it (present only with a winch).
struct WinchStatus {
  bool present = false;
  double deployed_length = 0.0;  ///< [m]
  double speed = 0.0;            ///< + paying out [m/s]
  double line_pull = 0.0;        ///< [N]
  unsigned deployed_links = 0;
  bool targeting = false;        ///< driving to target_length, else running at commanded_speed
  double commanded_speed = 0.0;  ///< [m/s]
  double target_length = 0.0;    ///< [m]
  unsigned links_added = 0, links_removed = 0;
};

/// An infinite bend radius (a straight joint), and any above it, as cable_state and /diagnostics publish it
/// (never a non-finite number) [m].
constexpr double kPublishedStraightRadius = 1e9;

/// The limits (cable.limits) as /diagnostics reports them: which is exceeded now and on which link, and the
/// cycles published while one was.
struct LimitStatus {
  bool tension = false, bend = false, clearance = false;  ///< exceeded at the last published instant
  int tension_link = 0, bend_link = 0, clearance_link = 0;  ///< 0-based slots (the message says link K = slot + 1)
  double tension_utilisation = 0.0, bend_utilisation = 0.0;  ///< the largest of each [-]
  double max_utilisation = 0.0;                              ///< [-]
  double min_bend_radius = kPublishedStraightRadius;         ///< [m], at most kPublishedStraightRadius
  double seabed_clearance = kPublishedStraightRadius;        ///< [m], at most that too
  unsigned cycles_in_excess = 0;  ///< published cycles with a limit exceeded, since start
  bool exceeded() const { return tension || bend || clearance; }
};

/// Takes the limits of the instant `snapshot` into `status` and counts the cycle when one is exceeded;
/// once per published cycle.
void updateLimitStatus(const SimulationSnapshot& snapshot, LimitStatus& status);

/// Counters and timing reported in cable_state and /diagnostics.
struct NodeStatus {
  double sim_time = 0.0;         ///< simulator's time since the last reset [s]
  double step_time = 0.0;        ///< wall time spent stepping in the last cycle [s]
  double lag = 0.0;              ///< simulated time behind the clock [s]
  double dropped_time = 0.0;     ///< simulated time given up so far because the lag exceeded ros.max_lag [s]
  double real_time_factor = 0.0;  ///< simulated s per wall s over the last window [-]
  double loop_rate = 0.0;        ///< cycles per wall second over the last window [Hz]
  double retried_share = 0.0;    ///< steps needing substeps in the last window [-]
  /// The energy balance's error since reset, of its scale [-]: RK4's drift (energyDrift), or the implicit
  /// step's rise (energyRise), followed at every step.
  double energy_error = 0.0;
  bool paused = false;
  bool diverged_recently = false;  ///< a step diverged since the last diagnostics
  bool dropped_recently = false;   ///< simulated time was dropped since the last diagnostics
  unsigned received = 0, rejected = 0, stale = 0, diverged = 0, retried = 0;
  unsigned refused_commands = 0;  ///< service requests and tuning parts refused since start
  WinchStatus winch;
  /// Axial elasticity (cable.axial_stiffness): the slack links now, the snaps and the largest tension
  /// since the last reset (from the snapshot: CableSimulator::snaps, largestTension).
  unsigned slack_links = 0, snaps = 0;
  double largest_tension = 0.0;  ///< [N]
  LimitStatus limits;            ///< cable.limits: exceeded now, where, and the cycles in excess
};

/// Sizes and names every message once: 3n joints, 2 + 3n transforms, 5 + kSceneMarkerCount + n markers (the
/// bodies drawn at `shapes`' sizes), n tensions (capacity for every slot), then shapes them for the
/// configured deployment (shapeOutputs(params.drumSlots())).
void prepareOutputs(const CableParams& params, const CableFrameNames& names, const std::string& world_frame,
                    CableOutputs& out, const BodyShapes& shapes = BodyShapes());
/// Shapes the messages for the deployed slots [first_link, n): 3 (n - first_link) joints, 2 + 3 (n -
/// first_link) transforms, n - first_link + 1 points of the cable's line. Names and frames move between the
/// messages and the stowed lists, one slot at a time, within the capacity reserved by prepareOutputs: no
/// allocation. Nothing to do when the shape is already that one.
void shapeOutputs(int first_link, CableOutputs& out);
/// The WinchStatus of an instant (present = false without a winch).
WinchStatus winchStatus(const OutputSource& source);

// The fill functions below need the messages shaped for the source's snapshot.first_link (shapeOutputs).

/// Joint states of the deployed links: the paper's coordinates [rad], rates [rad/s], effort = the springs'
/// torque [N m].
void fillJointState(const OutputSource& source, const ros::Time& stamp, sensor_msgs::JointState& msg);
/// TF: world -> paper frame (at `base_position` [m], half a turn about x), the deployed links' frames, the
/// load frame (axes parallel to the world frame).
void fillTransforms(const OutputSource& source, const Eigen::Vector3d& base_position, const ros::Time& stamp,
                    std::vector<geometry_msgs::TransformStamped>& transforms);
/// Markers: the deployed cable coloured by tension against `tension_scale` [N] (as a line and as cylinders
/// of its diameter; the drum's slots deleted), the load, the force arrows, the scale. The bodies' markers
/// are constant in their frames: only their stamps change.
/// With `colour_by` kUtilisation the cable is coloured by each link's utilisation instead (1 = red, a limit).
void fillMarkers(const OutputSource& source, double total_length, double tension_scale, const ros::Time& stamp,
                 visualization_msgs::MarkerArray& msg, MarkerColour colour_by = MarkerColour::kTension);
/// cable_state: tensions (per slot), forces (world frame), energies, the winch, timing and counters.
void fillCableState(const OutputSource& source, const NodeStatus& status, const ros::Time& stamp,
                    cable_msgs::CableState& msg);
/// The wrenches on the ROV and on the vessel (CableOutputs: wrench, wrench_world, base_wrench,
/// base_wrench_world) and the two bodies' frames, from the snapshot's (SimulationSnapshot::rov, ::vessel).
/// `base_position` is the base's rest position in the world frame [m].
void fillWrenches(const OutputSource& source, const Eigen::Vector3d& base_position, const ros::Time& stamp,
                  CableOutputs& out);
/// /diagnostics: one status with the level rules of docs/NODE.md (and the winch's values with a winch).
void fillDiagnostics(const NodeStatus& status, const ros::Time& stamp, diagnostic_msgs::DiagnosticArray& msg);

/// The diagnostics level and message for a status (docs/NODE.md: OK, WARN while a limit is exceeded (naming
/// it and the link), behind real time or past divergences, ERROR dropping time, diverging now, or most steps
/// needing substeps).
unsigned char diagnosticLevel(const NodeStatus& status, std::string& message);

}  // namespace cable_dynamics
