#pragma once
/// \file
/// \brief Time stepping of the cable: integrator, end conditions, divergence detection and recovery,
///        and the outputs users read (paper angles, link ends, tension, energies). ROS-free.

#include <string>

#include <Eigen/Core>

#include "cable_dynamics/params/cable_params.h"
#include "cable_dynamics/dynamics/chain_dynamics.h"

namespace cable_dynamics {

/// Everything published about one instant, in the paper frame (z down) unless stated.
struct SimulationSnapshot {
  double time = 0.0;       ///< simulated time since reset [s]
  Eigen::VectorXd q;       ///< (3n) paper coordinates [rad]
  Eigen::VectorXd qd;      ///< (3n) their rates [rad/s]
  ChainOutputs chain;      ///< ends, tension, forces, energies
  Eigen::Matrix3Xd axes;   ///< (3 x n) unit axis of each link, base end to far end [-]
  Eigen::VectorXd twists;  ///< (n) each link's total twist about the vertical, sigma = psi + phi [rad]
  double dissipated_energy = 0.0;  ///< taken out by drag, added mass and dampers since reset [J]
  double work_input = 0.0;         ///< done on the cable by the moving base and the load coupling [J]
  /// kinetic + potential + elastic + dissipated - work input: constant up to the integrator's error [J]
  double total_energy = 0.0;
};

/// Outcome of one step.
struct StepReport {
  bool ok = true;
  int substeps = 1;     ///< > 1 when the step was retried in smaller pieces after diverging
  std::string message;  ///< why the step failed (time and state), empty when ok
};

/// Steps the chain with a fixed dt (RK4, or the semi-implicit integrator of ChainDynamics). A step whose state is not finite, whose mass matrix fails,
/// whose angular velocity exceeds a limit or whose energy balance moves by more than 1e-4 of the energy
/// scale is discarded and retried as 2, 4, ..., 64 substeps; if that fails too, the state stays as it
/// was and the report says why.
class CableSimulator {
 public:
  /// Throws std::invalid_argument when the paper stiffness model has azimuth or torsion springs or
  /// dampers (singular at the vertical: use the bending model), naming the key.
  explicit CableSimulator(const CableParams& params);

  /// Back to the configured initial state and inputs at t = 0.
  void reset();
  /// After a divergence: the configured initial shape, at rest, under the base's present position; the
  /// time and the inputs (current, targets) carry on.
  void recover();
  /// Sets the state from paper coordinates (3n each) [rad, rad/s]; throws std::invalid_argument on a
  /// wrong size or a non-finite value.
  void setPaperState(const Eigen::VectorXd& q, const Eigen::VectorXd& qd);

  /// Advances by one time step dt.
  StepReport step();

  double time() const { return time_; }
  double dt() const { return dt_; }
  int links() const { return dynamics_.links(); }
  /// Per-link constants of this cable (derived once from the parameters).
  const LinkProperties& properties() const { return dynamics_.properties(); }
  const Eigen::VectorXd& state() const { return x_; }
  ChainDynamics& dynamics() { return dynamics_; }

  /// The paper coordinates (3n) [rad] and their rates (3n) [rad/s] of the present state.
  void paperCoordinates(Eigen::VectorXd& q, Eigen::VectorXd& qd) const { dynamics_.paperCoordinates(x_, q, qd); }

  /// Current outputs (evaluates the dynamics at the present state).
  void snapshot(SimulationSnapshot& out);

  // Inputs, all in one frame: world axes (REP-103, z up) with the origin at the base's rest position,
  // the frame of the config's motion offsets and current.

  /// Uniform current [m/s], replacing the configured field until reset().
  void setCurrent(const Eigen::Vector3d& current);
  /// External target for the load (modes anchored/attached) [m], [m/s]; replaces the configured motion
  /// until reset().
  void setLoadTarget(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity);
  /// External base position and velocity [m], [m/s]; replaces the configured motion until reset().
  void setBaseTarget(const Eigen::Vector3d& position, const Eigen::Vector3d& velocity);

  /// Largest stable RK4 time step estimated from the stiffest mode (string modes of the shortest link
  /// under the hanging tension, joint springs against link inertia) [s].
  double estimateStableTimeStep() const;

 private:
  EndInputs endsAt(double t) const;
  bool advance(double h);
  /// After a step: axes back on the unit sphere, and the checks for divergence.
  bool acceptable(double balance_before, double scale_before);
  /// Energy balance (kinetic + potential + elastic + dissipated - work input) at x, time t [J]; `scale`
  /// gets the sum of the magnitudes of its terms [J].
  double energyBalance(const Eigen::VectorXd& x, double t, double& scale);
  /// The same from the mechanical energy [J] and the sum of its terms' magnitudes [J].
  double balance(const Eigen::VectorXd& x, double mechanical, double magnitude, double& scale) const;

  CableParams params_;
  ChainDynamics dynamics_;
  double dt_;
  bool semi_implicit_;
  /// cached_balance_ holds the energy balance of the present state and k1_ its x' (nothing changed since)
  bool start_cached_ = false;
  double cached_balance_ = 0.0, cached_scale_ = 0.0;
  double time_ = 0.0;
  double omega_limit_;
  Eigen::VectorXd x_, x_start_, k1_, k2_, k3_, k4_, stage_;
  Eigen::VectorXd q_, qd_;
  Eigen::Vector3d initial_tip_ = Eigen::Vector3d::Zero();
  bool external_load_ = false, external_base_ = false;
  Eigen::Vector3d load_target_pos_ = Eigen::Vector3d::Zero(), load_target_vel_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d base_target_pos_ = Eigen::Vector3d::Zero(), base_target_vel_ = Eigen::Vector3d::Zero();
};

}  // namespace cable_dynamics
