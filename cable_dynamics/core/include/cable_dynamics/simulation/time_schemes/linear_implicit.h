#pragma once
/// \file
/// \brief The linearly implicit step in O(n): a two-stage Rosenbrock-W method (ROS2 with a controllable
///        spectral radius), each stage one pass of the articulated-body recursion with the stiff terms
///        folded into its inertias (stiff_articulated_body.h; docs/MODEL.md section 6, "Implicit integrator").

#include <Eigen/Core>

#include "cable_dynamics/dynamics/seabed_contact.h"
#include "cable_dynamics/dynamics/stiff_articulated_body.h"
#include "cable_dynamics/simulation/time_schemes/time_scheme.h"

namespace cable_dynamics {

/// ROS2 (Verwer, Spee, Blom and Hundsdorfer, SIAM J. Sci. Comput. 20, 1999) on the links' rotations and
/// angular velocities y = (phi, w), with the matrix W = I - gamma h A and A the Jacobian of
/// stiff_articulated_body.h (joint springs and dampers, drag, geometric stiffness, the seabed, a clamped
/// tip, the load's coupling):
///   (I - gamma h A) k1 = h F(y_n),
///   (I - gamma h A) k2 = h F(y_n + k1) - 2 k1,   y_{n+1} = y_n + 3/2 k1 + 1/2 k2.
/// Both stages solve (M + gamma h D + gamma^2 h^2 K) a = rhs by one O(n) recursion; the rotations live on
/// the links' frames (phi from x_n's, turned exactly). Properties that made it the choice:
/// - second order for any A (a W-method): the approximate bending Jacobian, the tension stiffness read from
///   the last solve and the Jacobian reused from the last step's second stage cost no order;
/// - A-stable on y' = lambda y (z = h lambda, exact A), with the amplification
///   R(z) = (1 + (1 - 2 gamma) z + (gamma^2 - 2 gamma + 1/2) z^2) / (1 - gamma z)^2 and R(inf) = -rho_inf through gamma = (1 - sqrt((1 - rho_inf) / 2)) / (1 + rho_inf):
///   rho_inf = 0 (gamma = 1 - 1/sqrt 2) is L-stable, rho_inf = 1 (gamma = 1/2) is the trapezoidal rule on
///   linear problems, which damps nothing and which a stiff, undamped nonlinear cable can drive unstable.
/// Cost: two evaluations of the loads, one linearization and two recursions per step; no heap allocation.
class LinearImplicitScheme : public TimeScheme {
 public:
  /// `axial`: the state carries each link's stretch and its rate (axial elasticity), stepped as the
  /// rotations are, its spring and damper folded into the recursion.
  LinearImplicitScheme(int links, double rho_infinity, bool body = false, bool axial = false);

  bool advance(ChainDynamics& dynamics, const EndConditions& ends, double t, double h, Eigen::VectorXd& x) override;
  /// Its power terms are the two stages' mean (second order), but a step's balance is not closed to the
  /// scheme's order under strong nonlinearity: not judged per step.
  bool balancesEnergy() const override { return false; }

  /// The next first stage linearizes afresh (its geometric stiffness from the external loads) instead of
  /// reusing the last second stage's Jacobians (a reset or a changed input).
  void forget() override { tensions_known_ = false; }
  /// Its balance closes to second order (the stages' mean powers): a rise beyond
  /// StepLimits::linear_energy_tolerance in one step is an event within it.
  double riseTolerance(const StepLimits& limits) const override { return limits.linear_energy_tolerance; }
  /// Its stages evaluate the rates afresh every step; the Jacobian it reuses does not read the thrust.
  void forgetRates() override {}

  std::unique_ptr<TimeScheme> clone() const override { return std::make_unique<LinearImplicitScheme>(*this); }

 private:
  /// A stage's powers [W]: what the base (and a winch's paid-out cable), the coupling and turning clamps put
  /// in, and the power of the drag, added-mass, damper and seabed forces (negative when they take energy
  /// out; the seabed's springs store theirs as contact energy).
  struct StagePower {
    double input, dissipative;
  };
  /// At the stage just solved; the seabed's losses at the velocities the stage took its dampers at
  /// (`contact_shift`: v + dv, see ContactVelocityShift), the stretches' at their rates shifted by
  /// `stretch_shift` [m/s] (n; read only with axial elasticity).
  StagePower stagePower(const ChainModel& model, const ChainData& data, const EndInputs& ends,
                        const ContactVelocityShift& contact_shift, const Eigen::VectorXd& stretch_shift) const;

  double gamma_;
  bool tensions_known_ = false;  ///< the solver holds the previous step's second stage's Jacobians and tensions
  StiffArticulatedBody solver_;
  Eigen::VectorXd stage_;  ///< x_n + k1 (state size)
  // (3 x n) per link: w_n, then stage 2's rphi [rad/s, then rad]; stage 1's kphi1 [rad], kw1 [rad/s], the base
  // end's displacement [m] and velocity change [m/s]; the stage-2 right-hand side's rotations and translations.
  Eigen::Matrix3Xd omega_, turn1_, spin1_, shift1_, push1_, rotation_, translation_;
  /// (3 x n) the velocity change at which a stage takes the seabed's dampers, per link: the base end's
  /// [m/s] and the angular velocity's [rad/s] (ContactVelocityShift).
  Eigen::Matrix3Xd contact_base_shift_, contact_omega_shift_;
  /// The ROV body (load.mode body) is stepped as a link is: its rotation vector and angular velocity in its
  /// own frame, with only its inertia in W (its own forces are slow beside the cable's: explicit).
  bool body_ = false;
  bool axial_ = false;
  /// Axial elasticity (n each): the stretch rates at the step's start [m/s], stage 1's ks'1 = h s''_1
  /// [m/s] and ks1 [m], stage 2's rate term r2 [m] and a scratch vector.
  Eigen::VectorXd stretch_rate_, stretch_spin1_, stretch_turn1_, stretch_rate2_, stretch_scratch_, stretch_zero_;
  /// The stage's shift of the stretch rates its dampers were solved at, over the start's [m/s] (n).
  Eigen::VectorXd stretch_shift_;
  Eigen::Vector3d body_turn1_ = Eigen::Vector3d::Zero(), body_spin1_ = Eigen::Vector3d::Zero();
};

}  // namespace cable_dynamics
