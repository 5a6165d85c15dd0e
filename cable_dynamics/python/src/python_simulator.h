#pragma once
/// \file
/// \brief The simulator as Python sees it: a CableSimulator built from a config, with argument checks on
///        every input (finite, in range, right size) and the outputs copied into shapes numpy users expect.
///        No physics here: every number comes from the core.

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "cable_dynamics/params/cable_params.h"
#include "cable_dynamics/simulation/cable_simulator.h"

namespace cable_dynamics {
namespace python {

/// One instant, copied out of a SimulationSnapshot. Paper frame (base at the origin, z down) unless
/// stated; rows are points or links, columns x, y, z.
struct Snapshot {
  double time = 0.0;               ///< [s] since reset
  Eigen::VectorXd q, qd;           ///< (3n) paper coordinates [rad] and rates [rad/s]
  Eigen::MatrixX3d link_ends;      ///< (n+1 x 3) base, then each link's far end (row n: the tip) [m]
  Eigen::MatrixX3d axes;           ///< (n x 3) unit axis of each link, base end to far end [-]
  Eigen::VectorXd tension;         ///< (n) force along each link at its base end, + pulls [N] (0 on a drum)
  double line_pull = 0.0;          ///< tension at the winch / the top [N]
  Eigen::Vector3d load_force;      ///< force the cable exerts on the load [N]
  Eigen::Vector3d base_force;      ///< force the cable exerts on the base [N]
  Eigen::Vector3d coupling_force;  ///< PD force of the anchor / ROV on the load [N]
  double kinetic_energy = 0.0, potential_energy = 0.0, elastic_energy = 0.0;  ///< [J]
  double dissipated_energy = 0.0, work_input = 0.0, total_energy = 0.0;       ///< [J]
  int first_link = 0;              ///< slots before it are on the winch's drum
  double deployed_length = 0.0;    ///< [m]
  double winch_speed = 0.0;        ///< + paying out [m/s]
  // The seabed (zeros and empty arrays without one).
  Eigen::MatrixX3d seabed_force;       ///< (n x 3) the bottom's force on each link, normal and friction [N]
  Eigen::VectorXd seabed_normal;       ///< (n) its normal part's magnitude [N]
  double grounded_length = 0.0;        ///< cable length in contact [m]
  double stuck_length = 0.0;           ///< of it, held by the static friction's anchors [m]
  double touchdown_arc_length = -1.0;  ///< from the base, where it first touches [m]; -1 while nothing does
  Eigen::Vector3d touchdown = Eigen::Vector3d::Zero();  ///< that point [m]
  double max_penetration = 0.0;        ///< [m]
  double contact_energy = 0.0;         ///< the contact springs' potential energy [J]
  /// Axial elasticity (cable.axial_stiffness; empty with rigid links): each link's strain [-], its
  /// stretched length [m], the tension at its far end [N], and how many links are slack.
  Eigen::VectorXd strain, stretched_length, far_tension;
  int slack_links = 0;
  /// The limits (cable.limits; dynamics/cable_limits.h): each joint's bend radius [m] (+inf straight),
  /// each link's utilisation [-], the smallest bend radius [m] and its link, the largest utilisation [-]
  /// and its link (0-based), and the seabed clearance [m] (+inf without a seabed).
  Eigen::VectorXd bend_radius, utilisation;
  double min_bend_radius = 0.0, max_utilisation = 0.0, seabed_clearance = 0.0;
  int min_bend_radius_link = 0, max_utilisation_link = 0;
};

/// The paper model's terms at the present state (paperModelAt), sizes 3n and 3n x 3n.
struct ModelTerms {
  std::vector<std::string> coordinates;  ///< (3n) joint_K_elevation, joint_K_azimuth, joint_K_torsion
  Eigen::VectorXd q, qd;                 ///< (3n) [rad], [rad/s]
  Eigen::MatrixXd M;                     ///< mass matrix [kg m^2]
  Eigen::VectorXd h;                     ///< Coriolis and centrifugal terms [N m]
  Eigen::VectorXd G;                     ///< generalized weight (gravity minus buoyancy) [N m]
  Eigen::MatrixXd K;                     ///< (tangent) stiffness [N m/rad]
  Eigen::VectorXd elastic;               ///< generalized elastic force [N m]
  Eigen::MatrixXd D;                     ///< damping [N m s/rad]
  double kinetic_energy = 0.0, potential_energy = 0.0, elastic_energy = 0.0;  ///< [J]
};

/// How Simulator.run ended: cable_sim's exit status for the same run (0 finished and reliable, 3 diverged,
/// 4 the CSV could not be written, 5 not reliable), the reason when it is not 0, and the lines cable_sim
/// prints after a run (substeps, energy balance, seabed).
struct RunOutcome {
  int status = 0;
  std::string message;
  std::vector<std::string> report;
};

/// Owns the parameters and the simulator. Every input is checked here and refused with
/// std::invalid_argument (Python: ValueError) naming the argument, its value and the allowed range.
class PythonSimulator {
 public:
  explicit PythonSimulator(const CableParams& params);

  /// Advances `steps` time steps (>= 1). Throws std::runtime_error with the core's message when a step
  /// fails (the state then stays at the last good step). Returns the substeps the steps took in all.
  long step(long steps);

  double time() const { return sim_.time(); }
  double dt() const { return sim_.dt(); }
  int links() const { return sim_.links(); }
  const CableParams& params() const { return params_; }
  std::vector<std::string> coordinates() const;

  Snapshot snapshot();
  /// cable_sim's run from the present instant (tools/sampled_run.h): `duration` [s] (> 0), a sample every
  /// `sample` [s] (> 0), each passed to `on_sample` (may be empty; a false return stops nothing, an
  /// exception it throws stops the run and is rethrown), and when `csv` is not empty cable_sim's CSV of
  /// those samples written there. Throws std::invalid_argument for a bad duration or sample,
  /// std::runtime_error when the CSV cannot be opened.
  RunOutcome run(double duration, double sample, const std::function<void(const Snapshot&)>& on_sample,
                 const std::string& csv);
  ModelTerms model();
  /// Paper coordinates (3n) [rad] and rates (3n) [rad/s].
  void setState(const Eigen::VectorXd& q, const Eigen::VectorXd& qd);

  void reset() { sim_.reset(); }
  /// Throws std::runtime_error with the solver's reason when there is no equilibrium.
  StaticSolution resetToEquilibrium();

  /// Uniform current, world axes (z up) [m/s]; fluid.current's range (the simulator checks every value).
  void setCurrent(const Eigen::Vector3d& current);
  /// The ROV's attachment point (load modes anchored / attached), world axes from the base's rest position
  /// [m], its velocity [m/s], the ROV's attitude as a unit quaternion (x, y, z, w; normalized here).
  void setLoadTarget(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity, const Eigen::Vector4d& xyzw);
  /// The ROV body's commanded thrust at its origin, body frame [N, N m] (load.mode body).
  void setBodyThrust(const Eigen::Vector3d& force, const Eigen::Vector3d& torque) { sim_.setBodyThrust(force, torque); }
  /// The station keeper's target: the ROV's origin [m] and attitude (x, y, z, w), world axes.
  void setBodyTarget(const Eigen::Vector3d& position, const Eigen::Vector4d& xyzw);
  /// The ROV body's pose and twist now (world axes; angular velocity in its frame).
  BodyPose bodyPose() { return sim_.bodyPose(); }
  /// The vessel's hang-off point, as setLoadTarget.
  void setBaseTarget(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity, const Eigen::Vector4d& xyzw);
  /// Winch speed [m/s], + pays out; |speed| <= winch.max_speed (refused beyond, not clamped, like the node).
  void commandWinchSpeed(double speed);
  /// Winch target length [m] in [winch.min_length, winch.max_length].
  void commandWinchLength(double length);

  bool hasWinch() const { return sim_.hasWinch(); }
  double energyDrift() const { return sim_.energyDrift(); }
  long retriedSteps() const { return sim_.retriedSteps(); }
  double stableTimeStep() const { return sim_.estimateStableTimeStep(); }

 private:
  CableParams params_;
  CableSimulator sim_;
  SimulationSnapshot snapshot_;  ///< reused between calls
  Snapshot toPython(const SimulationSnapshot& s) const;
};

}  // namespace python
}  // namespace cable_dynamics
