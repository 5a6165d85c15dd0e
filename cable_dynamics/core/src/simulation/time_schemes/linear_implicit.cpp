#include "cable_dynamics/simulation/time_schemes/linear_implicit.h"

#include <cassert>
#include <cmath>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "cable_dynamics/dynamics/fluid.h"
#include "cable_dynamics/dynamics/joint_torques.h"

namespace cable_dynamics {
namespace {

const Eigen::Vector3d kDown = Eigen::Vector3d::UnitZ();

/// sigma' for a link of axis u turning at omega: -omega.(e_z + u)/(1 + u_z) (kinematics.cpp).
inline double twistRate(const Eigen::Vector3d& omega, const Eigen::Vector3d& axis) {
  const double denominator = 1.0 + axis.z();
  return denominator > 1e-12 ? -omega.dot(kDown + axis) / denominator : -omega.dot(axis);
}

/// u turned by the rotation vector `turn` [rad] (Rodrigues), exactly a rotation at any angle.
inline Eigen::Vector3d turned(const Eigen::Vector3d& u, const Eigen::Vector3d& turn) {
  const double angle = turn.norm();
  if (angle < 1e-300) return u;
  const Eigen::Vector3d k = turn / angle;
  const double c = std::cos(angle), s = std::sin(angle);
  return c * u + s * k.cross(u) + ((1.0 - c) * k.dot(u)) * k;
}

}  // namespace

LinearImplicitScheme::LinearImplicitScheme(int links, double rho_infinity)
    : theta_(1.0 / (1.0 + rho_infinity)), solver_(links) {
  predicted_.setZero(StateLayout::size(links));
  for (Eigen::Matrix3Xd* m : {&omega_, &rotation_, &translation_}) m->setZero(3, links);
}

bool LinearImplicitScheme::advance(ChainDynamics& f, const EndConditions& end_conditions, double t, double h,
                                   Eigen::VectorXd& x) {
  assert(x.size() == f.stateSize());
  if (!x.allFinite()) return false;
  const ChainModel& model = f.model();
  const ChainData& data = f.data();
  const int n = f.links(), first = model.firstLink();
  const double th = theta_ * h;
  // Predictor: backward Euler over theta h from x_n, linearized: (M + th D + th^2 K) a_p = g(x_n) - th K w_n.
  const EndInputs start = end_conditions.at(t);
  f.computeLoads(x, start);
  // The predictor only has to be consistent (x_p is then O(h^2) from the evaluation point whatever its
  // Jacobian): it reuses the last corrector's, linearized O(h) away, and saves a linearization a step.
  if (!tensions_known_) solver_.linearize(model, data, start, false);
  solver_.clearExtra();
  for (int k = first; k < n; ++k) omega_.col(k) = x.segment<3>(StateLayout::omega(k));
  translation_.setZero();  // K reads rotations only
  const Eigen::Vector3d tip_rate =
      start.load_coupled ? Eigen::Vector3d(data.tip_velocity - start.target_velocity) : Eigen::Vector3d::Zero();
  solver_.addJacobianTimes(model, -th, 0.0, omega_, data.clamp_omega, translation_, tip_rate);
  solver_.solve(model, data, th, th * th);
  predicted_ = x;
  for (int k = first; k < n; ++k) {
    const StiffLinkTerms& terms = solver_.link(k);
    const Eigen::Vector3d change = th * terms.angular_acc;  // dw_p
    rotation_.col(k) = change;
    translation_.col(k) = th * terms.delta_acc;  // the base end's velocity change
    const Eigen::Vector3d omega = omega_.col(k) + change;
    const Eigen::Vector3d axis = x.segment<3>(StateLayout::axis(k));
    predicted_.segment<3>(StateLayout::axis(k)) = turned(axis, th * omega);
    predicted_(StateLayout::twist(k)) += th * twistRate(omega, axis);
    predicted_.segment<3>(StateLayout::omega(k)) = omega;
  }
  const Eigen::Vector3d tip_change = th * solver_.tipDelta();
  if (!predicted_.allFinite()) return false;
  // Corrector about x_p: (M + th D + th^2 K) a = g(x_p) + (D + th K) dw_p, dw = h a.
  const EndInputs middle = end_conditions.at(t + th);
  f.computeLoads(predicted_, middle);
  solver_.linearize(model, data, middle, true);  // the predictor's tensions
  tensions_known_ = true;
  solver_.clearExtra();
  solver_.addJacobianTimes(model, th, 1.0, rotation_, Eigen::Vector3d::Zero(), translation_, tip_change);
  solver_.solve(model, data, th, th * th);
  // The powers at the evaluation point: drag, dampers, added mass (with the solved accelerations), and
  // what the base, the coupling and a turning clamp put in.
  double added_power = 0.0;
  for (int k = first; k < n; ++k) {
    const LinkConstants& c = model.of(k);
    const LinkBlock& block = data.links.of(k);
    const int i = LinkBlocks::lane(k);
    const StiffLinkTerms& terms = solver_.link(k);
    Vec3 base_weight, axis_weight;
    linkAddedMassPowerWeights(c, i, block.u[i], block.axis_rate[i], block.base_vel[i], base_weight, axis_weight);
    const Vec3 axis_acc = toVec3(terms.angular_acc.cross(toEigen(block.u[i]))) + block.beta[i];
    added_power += dot(base_weight, block.known_acc[i] + toVec3(terms.delta_acc)) + dot(axis_weight, axis_acc);
  }
  const Eigen::Vector3d tip_acc = data.tip_known_acc + solver_.tipDelta();
  added_power -= (model.load().inertia - model.load().mass) * tip_acc.dot(data.tip_velocity);
  const double damping_power = damperPower(model, data);
  const Eigen::Vector3d exit_velocity = data.links.get(&LinkBlock::base_vel, first);
  const double input_power = solver_.baseForce().dot(exit_velocity) + data.coupling.dot(data.tip_velocity) +
                             data.clamp_torque.dot(data.clamp_omega);
  for (int k = first; k < n; ++k) {
    const Eigen::Vector3d change = h * solver_.link(k).angular_acc;
    const Eigen::Vector3d omega = omega_.col(k);
    const Eigen::Vector3d evaluated = omega + theta_ * change;  // w at the evaluation point
    const Eigen::Vector3d axis = x.segment<3>(StateLayout::axis(k));
    x.segment<3>(StateLayout::axis(k)) = turned(axis, h * evaluated);
    // sigma' at the evaluation point, with x_p's axis (O(h^2) from it: second order still).
    x(StateLayout::twist(k)) += h * twistRate(evaluated, predicted_.segment<3>(StateLayout::axis(k)));
    x.segment<3>(StateLayout::omega(k)) = omega + change;
  }
  x(StateLayout::dissipated(n)) -= h * (data.drag_power + added_power + damping_power);
  x(StateLayout::workInput(n)) += h * input_power;
  return x.allFinite();
}

}  // namespace cable_dynamics
