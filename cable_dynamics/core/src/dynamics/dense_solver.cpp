#include "cable_dynamics/dynamics/dense_solver.h"

#include <cassert>

#include <Eigen/Geometry>

#include "cable_dynamics/dynamics/fluid.h"
#include "cable_dynamics/dynamics/link_rates.h"
#include "cable_dynamics/dynamics/rov_body.h"

namespace cable_dynamics {
namespace {

/// Moment `order` (0, 1, 2) about the base end of link k's translational inertia: the integral of
/// s^order A ds (A = m' I + m_a' (I - u u^T)) plus the attachments' sum (m_p + m_pa) s_p^order I [kg m^order].
Eigen::Matrix3d momentTensor(const ChainDeployment& deployed, int k, const Eigen::Vector3d& axis, int order) {
  const LinkConstants& c = deployed.of(k);
  const int i = k % kBlockLanes;
  const double l = c.length[i];
  const double isotropic = order == 0 ? c.translational[i] : order == 1 ? c.half_moment[i] : c.third_moment[i];
  const double power = order == 0 ? l : order == 1 ? 0.5 * l * l : l * l * l / 3.0;
  return isotropic * Eigen::Matrix3d::Identity() - (c.added[i] * power) * axis * axis.transpose();
}

/// The zeroth moments per link (O(n)).
void inertiaTensors(const ChainModel& model, ChainData& data) {
  for (int k = 0; k < model.links(); ++k) data.dense.tensor[k] = momentTensor(data.deployed, k, data.links.get(&LinkBlock::u, k), 0);
}

/// Power of the added-mass force on link k [W], from its base-end and axis accelerations.
double addedMassPower(const ChainData& data, int k, const Eigen::Vector3d& base_acc,
                      const Eigen::Vector3d& axis_acc) {
  const LinkBlock& block = data.links.of(k);
  const int i = LinkBlocks::lane(k);
  Vec3 base_weight, axis_weight;
  linkAddedMassPowerWeights(data.deployed.of(k), i, block.u[i], block.axis_rate[i], block.base_vel[i], base_weight, axis_weight);
  return dot(base_weight, toVec3(base_acc)) + dot(axis_weight, toVec3(axis_acc));
}

}  // namespace

void assembleGeneralizedForces(const ChainModel& model, ChainData& data) {
  assert(data.dense.allocated());
  DenseWorkspace& w = data.dense;
  const LinkBlocks& links = data.links;
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  const double load_inertia = model.load().inertia;
  inertiaTensors(model, data);
  // Outboard inertia B_k = sum_{j>k} l_j A_j + load, and the known-acceleration (bias) integrals.
  Eigen::Matrix3d outboard = load_inertia * identity;
  Eigen::Vector3d outboard_force = data.load_external - load_inertia * data.tip_known_acc;
  if (model.body().active) {  // an ROV body on a ball joint: its 3x3 mass at the tip and its bias (rov_body.h),
                              // as in the recursion (articulated_body.cpp)
    outboard += data.body.tip_mass;
    outboard_force -= data.body.tip_mass * data.tip_known_acc + data.body.tip_bias;
  }
  for (int k = model.links() - 1; k >= 0; --k) {
    w.outboard[k] = outboard;
    const double l = data.deployed.get(&LinkConstants::length, k);
    const Eigen::Vector3d axis = links.get(&LinkBlock::u, k);
    const Eigen::Matrix3d& a0 = w.tensor[k];
    const Eigen::Matrix3d a1 = momentTensor(data.deployed, k, axis, 1), a2 = momentTensor(data.deployed, k, axis, 2);
    const Eigen::Vector3d known = links.get(&LinkBlock::known_acc, k), beta = links.get(&LinkBlock::beta, k);
    w.inertial_force.col(k) = a0 * known + a1 * beta;
    w.inertial_moment.col(k) = a1 * known + a2 * beta;
    // Generalized force of link k's angular velocity: moment about joint k of everything outboard of it.
    const Eigen::Vector3d lever = l * outboard_force + links.get(&LinkBlock::moment, k) - w.inertial_moment.col(k);
    const Eigen::Vector3d omega = links.get(&LinkBlock::omega, k);
    const double ip = data.deployed.get(&LinkConstants::polar, k), it = data.deployed.get(&LinkConstants::thick_transverse, k);
    const Eigen::Vector3d spin_axis = axis * axis.dot(omega);
    const Eigen::Vector3d angular_momentum = it * (omega - spin_axis) + ip * spin_axis;
    w.rhs.segment<3>(3 * k) = axis.cross(lever) + links.get(&LinkBlock::torque, k) - omega.cross(angular_momentum);
    outboard_force += links.get(&LinkBlock::force, k) - w.inertial_force.col(k);
    outboard += a0;
  }
}

void assembleMassMatrix(const ChainModel& model, ChainData& data) {
  DenseWorkspace& w = data.dense;
  const LinkBlocks& links = data.links;
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  // M_rj = -l_r [u_r]x E_j [u_j]x for r < j with E_j = T1_j + l_j B_j (T1_j = l_j^2/2 A_j + attachments,
  // momentTensor); diagonal blocks use T2_j + l_j^2 B_j plus the thickness inertia of the link.
  for (int j = 0; j < model.links(); ++j) {
    const double l = data.deployed.get(&LinkConstants::length, j);
    const Eigen::Vector3d axis = links.get(&LinkBlock::u, j);
    const Eigen::Matrix3d uj = skew(axis);
    w.column[j] = (momentTensor(data.deployed, j, axis, 1) + l * w.outboard[j]) * uj;
    const Eigen::Matrix3d diagonal = -uj * (momentTensor(data.deployed, j, axis, 2) + (l * l) * w.outboard[j]) * uj;
    const Eigen::Matrix3d rotation_inertia =
        data.deployed.get(&LinkConstants::thick_transverse, j) * (identity - axis * axis.transpose()) +
        data.deployed.get(&LinkConstants::polar, j) * axis * axis.transpose();
    w.mass_matrix.block<3, 3>(3 * j, 3 * j) = diagonal + rotation_inertia;
    for (int r = 0; r < j; ++r) {
      const Eigen::Matrix3d block =
          -data.deployed.get(&LinkConstants::length, r) * skew(links.get(&LinkBlock::u, r)) * w.column[j];
      w.mass_matrix.block<3, 3>(3 * r, 3 * j) = block;
      w.mass_matrix.block<3, 3>(3 * j, 3 * r) = block.transpose();
    }
  }
}

void denseJointForces(const ChainModel& model, ChainData& data, const Eigen::VectorXd& omega_rate) {
  // Accelerations of the link axes and base ends with the solved angular accelerations, then the force
  // on everything outboard of each joint from Newton's law for that part: J_k = sum (A a - f).
  DenseWorkspace& w = data.dense;
  const LinkBlocks& links = data.links;
  Eigen::Vector3d acc = links.get(&LinkBlock::known_acc, 0);  // the base's own acceleration
  for (int k = 0; k < model.links(); ++k) {
    w.axis_acc.col(k) = omega_rate.segment<3>(3 * k).cross(links.get(&LinkBlock::u, k)) + links.get(&LinkBlock::beta, k);
    w.link_base_acc.col(k) = acc;
    acc += data.deployed.get(&LinkConstants::length, k) * w.axis_acc.col(k);
  }
  data.load_force = model.load().inertia * acc - data.load_external;  // acc: the tip's
  if (model.body().active) data.load_force += finishRovBody(model.body(), acc, data.body);
  Eigen::Vector3d outboard = data.load_force;
  // The load's added-mass force -m_a a_tip, then the links' (articulated_body.cpp alike).
  data.added_mass_power = -(model.load().inertia - model.load().mass) * acc.dot(data.tip_velocity);
  for (int k = model.links() - 1; k >= 0; --k) {
    const Eigen::Matrix3d a1 = momentTensor(data.deployed, k, links.get(&LinkBlock::u, k), 1);
    outboard += w.tensor[k] * w.link_base_acc.col(k) + a1 * w.axis_acc.col(k) - links.get(&LinkBlock::force, k);
    data.joint_force.col(k) = outboard;
    data.added_mass_power += addedMassPower(data, k, w.link_base_acc.col(k), w.axis_acc.col(k));
  }
}

bool solveDense(const ChainModel& model, ChainData& data) {
  DenseWorkspace& w = data.dense;
  assembleGeneralizedForces(model, data);
  assembleMassMatrix(model, data);
  w.llt.compute(w.mass_matrix);
  if (w.llt.info() != Eigen::Success) return false;
  w.omega_rate = w.rhs;
  w.llt.solveInPlace(w.omega_rate);
  denseJointForces(model, data, w.omega_rate);
  for (int k = 0; k < model.links(); ++k) data.links.set(&LinkBlock::omega_rate, k, w.omega_rate.segment<3>(3 * k));
  return true;
}

}  // namespace cable_dynamics
