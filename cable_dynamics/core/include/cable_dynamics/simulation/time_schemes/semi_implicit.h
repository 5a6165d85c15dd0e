#pragma once
/// \file
/// \brief Linearized backward Euler in the angular velocities (first order, stable for stiff springs and
///        strong drag), with the Jacobians of the generalized forces by central differences.

#include <Eigen/LU>

#include "cable_dynamics/simulation/time_schemes/time_scheme.h"

namespace cable_dynamics {

/// M dw = h (Q(x_n) + K_r h (w_n + dw) + K_w dw), with K_r and K_w the Jacobians of the generalized
/// forces (springs, dampers, drag, coupling) with respect to small rotations of each link and to the
/// angular velocities; then the orientations advance with the new velocities. The Jacobians cost 12n
/// evaluations of the O(n) forces and the dense solve O(n^3): a reference for stiff cables, not fast.
/// An ROV body (load.mode body) rides on the tip as its 3x3 mass and bias in the forces and the mass
/// matrix (rov_body.h); its own rotation takes the angular acceleration the step's mean tip acceleration
/// gives, explicitly (symplectic Euler: the new angular velocity turns the attitude), as the implicit
/// scheme treats it (linear_implicit.cpp).
class SemiImplicitScheme : public TimeScheme {
 public:
  /// `body`: the state carries an ROV body's attitude and angular velocity (StateLayout::kBody).
  SemiImplicitScheme(int links, bool body);

  bool advance(ChainDynamics& dynamics, const EndConditions& ends, double t, double h, Eigen::VectorXd& x) override;
  bool balancesEnergy() const override { return false; }

  std::unique_ptr<TimeScheme> clone() const override { return std::make_unique<SemiImplicitScheme>(*this); }

 private:
  /// Step of the central differences in the angular velocities [rad/s] and the rotations [rad].
  static constexpr double kPerturbation = 1e-6;

  Eigen::MatrixXd jacobian_velocity_, jacobian_rotation_, system_;  ///< (3n x 3n)
  Eigen::VectorXd perturbed_;                                       ///< (state size)
  Eigen::VectorXd force_plus_, force_minus_, velocity_, step_rhs_, delta_, mean_rate_;  ///< (3n)
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
};

}  // namespace cable_dynamics
