#include "cable_dynamics/simulation/time_schemes/semi_implicit.h"

#include <cassert>

#include <Eigen/Geometry>

#include "cable_dynamics/dynamics/dense_solver.h"
#include "cable_dynamics/dynamics/forces/axial_spring.h"
#include "cable_dynamics/dynamics/forces/power_balance.h"
#include "cable_dynamics/dynamics/link_rates.h"
#include "cable_dynamics/dynamics/rov_body.h"

namespace cable_dynamics {

SemiImplicitScheme::SemiImplicitScheme(int links, bool body) {
  const int dof = 3 * links;
  for (Eigen::MatrixXd* m : {&jacobian_velocity_, &jacobian_rotation_, &system_}) m->setZero(dof, dof);
  for (Eigen::VectorXd* v : {&force_plus_, &force_minus_, &velocity_, &step_rhs_, &delta_, &mean_rate_}) {
    v->setZero(dof);
  }
  perturbed_.setZero(StateLayout::size(links, body));
  lu_ = Eigen::PartialPivLU<Eigen::MatrixXd>(dof);
}

bool SemiImplicitScheme::advance(ChainDynamics& f, const EndConditions& end_conditions, double t, double h,
                                 Eigen::VectorXd& x) {
  assert(x.size() == f.stateSize());
  if (!x.allFinite()) return false;
  const EndInputs ends = end_conditions.at(t);
  const int n = f.links(), dof = 3 * n;
  const double eps = kPerturbation;
  // Jacobians of the generalized forces (external, springs, dampers and the velocity terms) with respect
  // to the angular velocities and to small rotations of each link, by central differences. Each column
  // costs one O(n) force evaluation, O(n^2) in all: cheaper than the O(n^3) solve below.
  perturbed_ = x;
  for (int j = 0; j < dof; ++j) {
    const int index = StateLayout::omega(j / 3) + j % 3;
    perturbed_(index) = x(index) + eps;
    f.generalizedForces(perturbed_, ends, true, force_plus_);
    perturbed_(index) = x(index) - eps;
    f.generalizedForces(perturbed_, ends, true, force_minus_);
    perturbed_(index) = x(index);
    jacobian_velocity_.col(j) = (force_plus_ - force_minus_) / (2.0 * eps);
  }
  // The rotation Jacobian is the stiffness: it leaves the dampers out. (The paper's elevation damper
  // turns with the azimuth, which is ill-conditioned near the vertical; its rate Jacobian above is not.)
  for (int j = 0; j < dof; ++j) {
    const int k = j / 3;
    const Eigen::Vector3d axis = x.segment<3>(StateLayout::axis(k)).normalized();
    const Eigen::Vector3d turn = Eigen::Vector3d::Unit(j % 3);
    // A rotation by e about `turn` moves u by e turn x u and sigma by -e turn.(e_z + u)/(1 + u_z).
    const double twist_rate = twistRate(turn, axis);
    for (const double sign : {1.0, -1.0}) {
      perturbed_.segment<3>(StateLayout::axis(k)) = (axis + sign * eps * turn.cross(axis)).normalized();
      perturbed_(StateLayout::twist(k)) = x(StateLayout::twist(k)) + sign * eps * twist_rate;
      f.generalizedForces(perturbed_, ends, false, sign > 0 ? force_plus_ : force_minus_);
    }
    perturbed_.segment<3>(StateLayout::axis(k)) = x.segment<3>(StateLayout::axis(k));
    perturbed_(StateLayout::twist(k)) = x(StateLayout::twist(k));
    jacobian_rotation_.col(j) = (force_plus_ - force_minus_) / (2.0 * eps);
  }
  // Linearized backward Euler in the velocities: M dw = h (Q(x_n) + K_r h (w_n + dw) + K_w dw), with
  // K_r, K_w the Jacobians above, then the orientations advance with the new velocities.
  f.generalizedForces(x, ends, true, force_plus_);
  system_ = f.massMatrix() - h * jacobian_velocity_ - (h * h) * jacobian_rotation_;
  const ChainData& data = f.data();
  for (int k = 0; k < n; ++k) velocity_.segment<3>(3 * k) = data.links.get(&LinkBlock::omega, k);
  step_rhs_.noalias() = jacobian_rotation_ * velocity_;
  step_rhs_ = h * (force_plus_ + h * step_rhs_);
  lu_.compute(system_);
  delta_.noalias() = lu_.solve(step_rhs_);
  if (!delta_.allFinite()) return false;
  // Forces along the cable and the powers, with the step's mean angular acceleration.
  mean_rate_ = delta_ / h;
  denseJointForces(f.model(), f.data(), mean_rate_);
  // The balance's powers from the one place every scheme takes them (forces/power_balance.h): with the
  // seabed's dissipation and the turning clamps' work, which a sum of its own here had left out.
  const double loss_power =
      lossPower(f.model(), data, data.added_mass_power, data.contact_dissipation, axialLoss(f.model(), data));
  const double input_power = endsInputPower(f.model(), data, ends, data.joint_force.col(f.deployed().firstLink()));
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector3d omega = data.links.get(&LinkBlock::omega, k) + delta_.segment<3>(3 * k);
    const Eigen::Vector3d axis = data.links.get(&LinkBlock::u, k);
    const double angle = h * omega.norm();
    Eigen::Vector3d turned = axis;
    if (angle > 0.0) turned = Eigen::AngleAxisd(angle, omega.normalized()) * axis;
    x.segment<3>(StateLayout::axis(k)) = turned;
    x(StateLayout::twist(k)) += h * twistRate(omega, axis);
    x.segment<3>(StateLayout::omega(k)) = omega;
  }
  if (f.model().body().active) {
    // The ROV body's angular acceleration at the step's mean tip acceleration (denseJointForces ran
    // finishRovBody with it), explicitly; its new angular velocity (body frame) turns the attitude.
    const Eigen::Vector3d body_omega = x.segment<3>(StateLayout::bodyOmega(n)) + h * data.body.acceleration.tail<3>();
    x.segment<4>(StateLayout::bodyAttitude(n)) = turnedAttitude(x.segment<4>(StateLayout::bodyAttitude(n)), h * body_omega);
    x.segment<3>(StateLayout::bodyOmega(n)) = body_omega;
  }
  x(StateLayout::dissipated(n)) -= h * loss_power;
  x(StateLayout::workInput(n)) += h * input_power;
  return x.allFinite();
}

}  // namespace cable_dynamics
