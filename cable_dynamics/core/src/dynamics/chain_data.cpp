#include "cable_dynamics/dynamics/chain_data.h"

namespace cable_dynamics {

void DenseWorkspace::allocate(int n) {
  // 3n x 3n: 72 MB at n = 1000, which the recursive formulation with RK4 never touches.
  const int dof = 3 * n;
  if (mass_matrix.rows() == dof) return;
  mass_matrix.setZero(dof, dof);
  llt = Eigen::LLT<Eigen::MatrixXd>(dof);
  rhs.setZero(dof);
  omega_rate.setZero(dof);
  tensor.assign(n, Eigen::Matrix3d::Zero());
  outboard.assign(n, Eigen::Matrix3d::Zero());
  column.assign(n, Eigen::Matrix3d::Zero());
  for (Eigen::Matrix3Xd* m : {&inertial_force, &inertial_moment, &axis_acc, &link_base_acc}) m->setZero(3, n);
}

ChainData::ChainData(const ChainModel& model)
    : deployed(model.initialDeployment()), links(model.links()), current(FluidParams{}), azimuths(model.links()) {
  const int n = model.links();
  // Every lane starts as a finite link along the vertical: the padding lanes stay so (the kinematics
  // normalize every lane's axis), and zero in everything else.
  for (int b = 0; b < links.blocks(); ++b) {
    links.block(b) = LinkBlock{};
    for (int i = 0; i < kBlockLanes; ++i) links.block(b).u.set(i, {0.0, 0.0, 1.0});
  }
  for (Eigen::Matrix3Xd* m : {&joint_force, &spring_torque, &damping_torque}) m->setZero(3, n);
  clamp_axis = model.configured().clamp_axis;
  clamp_twist = model.configured().clamp_twist;
  paper_q.setZero(3 * n);
  paper_qd.setZero(3 * n);
  paper_psi.setZero(n);
  // The dense workspace: at construction when the configuration solves densely (no allocation later).
  if (model.formulation() == Formulation::kPaper) dense.allocate(n);
  if (model.seabedContact().anchored()) anchors.allocate(n, model.seabedContact().points);
}

}  // namespace cable_dynamics
