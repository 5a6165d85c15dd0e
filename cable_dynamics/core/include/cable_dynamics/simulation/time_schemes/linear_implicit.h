#pragma once
/// \file
/// \brief The linearly implicit theta step in O(n): predictor and corrector, each one pass of the
///        articulated-body recursion with the stiff terms folded into its inertias
///        (stiff_articulated_body.h; docs/MODEL.md section 6, "Implicit integrator").

#include <Eigen/Core>

#include "cable_dynamics/dynamics/stiff_articulated_body.h"
#include "cable_dynamics/simulation/time_schemes/time_scheme.h"

namespace cable_dynamics {

/// The theta method y_{n+1} = y_n + h f(y_n + theta (y_{n+1} - y_n)) on the angular velocities w and
/// the rotations, linearized in two stages that both solve (M + theta h D + theta^2 h^2 K) a = rhs by one
/// O(n) recursion (K, D: the Jacobians of stiff_articulated_body.h):
/// - predictor, a linearized backward-Euler step of theta h from x_n (with the previous corrector's K and D):
///   a_p from rhs = g(x_n) - theta h K w_n,
///   dw_p = theta h a_p, w_p = w_n + dw_p, axes turned by theta h w_p: x_p, an O(h^2) estimate of the
///   state at the evaluation point;
/// - corrector, the theta step linearized about x_p: rhs = g(x_p) + (D + theta h K) dw_p, dw = h a,
///   w_{n+1} = w_n + dw, the axes turned by h (w_n + theta dw).
/// theta = 1 / (1 + rho_inf): rho_inf = 1 is the implicit midpoint rule (second order, no numerical
/// damping, A-stable; for a linear system the linearization is exact and it is the trapezoidal rule),
/// rho_inf < 1 damps the highest modes to rho_inf per step (first order), rho_inf = 0 is backward Euler.
/// Because x_p is O(h^2) from the evaluation point, forces left out of K and D (or approximated there)
/// cost no order. Cost: two evaluations of the loads and two recursions per step; no heap allocation.
class LinearImplicitScheme : public TimeScheme {
 public:
  LinearImplicitScheme(int links, double rho_infinity);

  bool advance(ChainDynamics& dynamics, const EndConditions& ends, double t, double h, Eigen::VectorXd& x) override;
  /// Its power terms are integrated at the evaluation point (second order at rho_inf = 1), but a step's
  /// balance is not closed to the scheme's order under strong nonlinearity: not judged per step.
  bool balancesEnergy() const override { return false; }

  double theta() const { return theta_; }
  /// The next predictor linearizes afresh (its geometric stiffness from the external loads) instead of
  /// reusing the last corrector's Jacobians (a reset or a changed input).
  void forget() override { tensions_known_ = false; }

 private:
  double theta_;
  bool tensions_known_ = false;  ///< the solver holds the previous step's corrector's Jacobians and tensions
  StiffArticulatedBody solver_;
  Eigen::VectorXd predicted_;                          ///< x_p (state size)
  Eigen::Matrix3Xd omega_, rotation_, translation_;    ///< (3 x n) scratch [rad/s], [rad/s], [m/s]
};

}  // namespace cable_dynamics
