#include "cable_dynamics/dynamics/joint_torques.h"

#include <cmath>

#include "cable_dynamics/dynamics/forces/joint_springs.h"
#include "cable_dynamics/dynamics/forces/tip_clamp.h"
#include "cable_dynamics/dynamics/joint_geometry.h"
#include "cable_dynamics/dynamics/paper_coordinates.h"
#include "cable_dynamics/dynamics/paper_model.h"
#include "cable_dynamics/dynamics/state_layout.h"

namespace cable_dynamics {
namespace {

/// The paper's springs and dampers act on the generalized coordinates: Q = -K q - C q'. Mapped to world
/// torques by virtual power: tau = -Q_te n + (Q_psi - Q_phi cos te)/sin te e - Q_phi u, with Q in the
/// absolute angles (Q_psi_i = Q_a_i - Q_a_{i+1}). Azimuth and torsion springs have no limit as
/// sin te -> 0 unless Q_psi = Q_phi: the paper's K is singular there (docs/MODEL.md section 5).
void paperSpringTorques(const ChainModel& model, ChainData& data, const Eigen::VectorXd& x) {
  const int n = model.links();
  const LinkProperties& p = data.deployed.properties();
  Eigen::Vector3d q_next = Eigen::Vector3d::Zero(), c_next = Eigen::Vector3d::Zero();
  // Paper coordinates in a forward pass, then torques backwards so Q_a_{i+1}, Q_t_{i+1} are at hand.
  paperCoordinates(n, data.azimuths, x, data.paper_q, data.paper_qd);
  double psi_sum = 0.0;
  for (int k = 0; k < n; ++k) data.paper_psi(k) = (psi_sum += data.paper_q(3 * k + 1));
  for (int k = n - 1; k >= 0; --k) {
    const Eigen::Vector3d stiffness(p.stiffness_elevation(k), p.stiffness_azimuth(k), p.stiffness_torsion(k));
    const Eigen::Vector3d damping(p.damping_elevation(k), p.damping_azimuth(k), p.damping_torsion(k));
    const Eigen::Vector3d q_spring = -stiffness.cwiseProduct(data.paper_q.segment<3>(3 * k));
    const Eigen::Vector3d q_damper = -damping.cwiseProduct(data.paper_qd.segment<3>(3 * k));
    const double te = data.paper_q(3 * k);
    const Eigen::Vector3d axis = data.links.get(&LinkBlock::u, k);
    Eigen::Vector3d nvec, evec;
    eulerAxes(te, data.paper_psi(k), nvec, evec);
    const double sine = std::sin(te), cosine = std::cos(te);
    const auto to_torque = [&](const Eigen::Vector3d& own, const Eigen::Vector3d& next) -> Eigen::Vector3d {
      const double q_te = own(0), q_psi = own(1) - next(1), q_phi = own(2) - next(2);
      const double across = std::abs(sine) > kVerticalSine ? (q_psi - q_phi * cosine) / sine : 0.0;
      return -q_te * nvec + across * evec - q_phi * axis;
    };
    data.spring_torque.col(k) = to_torque(q_spring, q_next);
    data.damping_torque.col(k) = to_torque(q_damper, c_next);
    q_next = q_spring;
    c_next = q_damper;
  }
}

/// Joint k couples link k-1 (the base's clamp, LinkProperties::clamp_axis, for k = 0) and link k.
void bendingSpringTorques(const ChainModel& model, ChainData& data, const Eigen::VectorXd& x) {
  const LinkProperties& p = data.deployed.properties();
  const LinkBlocks& links = data.links;
  const int first = data.deployed.firstLink();
  for (int k = first; k < model.links(); ++k) {
    const bool inner = k > first;  // joint `first` is the base's
    const Eigen::Vector3d prev = inner ? links.get(&LinkBlock::u, k - 1) : data.clamp_axis;
    const Eigen::Vector3d axis = links.get(&LinkBlock::u, k);
    const JointGeometry g =
        jointGeometry(prev, axis, x(StateLayout::twist(k)), inner ? x(StateLayout::twist(k - 1)) : data.clamp_twist);
    // Bend: V = 1/2 k_b beta^2 (forces/joint_springs.h), and between two links folded onto each other
    // their fold stop (forces/fold_stop.h).
    Eigen::Vector3d bend_torque = bendSpringTorque(p.stiffness_elevation(k), g.bend, g.sine, g.cross);
    if (inner && g.cosine < 0.0) bend_torque += model.foldStop(p, k).torque(g.bend, g.sine, g.cross);
    // Twist: a rotation dTheta of link k changes it by -(prev + u_k)/(1 + prev.u_k) . dTheta.
    const Eigen::Vector3d mean_axis = (prev + axis) / (1.0 + g.cosine);
    const Eigen::Vector3d twist_torque = p.stiffness_torsion(k) * g.twist * mean_axis;
    // Dampers on the relative angular velocity: across the mean axis (bending) and about it (twist).
    const Eigen::Vector3d relative =
        links.get(&LinkBlock::omega, k) - (inner ? links.get(&LinkBlock::omega, k - 1) : data.clamp_omega);
    const Eigen::Vector3d direction = meanAxis(prev, axis, axis);  // defined at a fold of pi too
    const double about = relative.dot(direction);
    const Eigen::Vector3d damper =
        -p.damping_elevation(k) * (relative - about * direction) - p.damping_torsion(k) * about * direction;
    data.spring_torque.col(k) += bend_torque + twist_torque;
    data.damping_torque.col(k) += damper;
    if (inner) {
      data.spring_torque.col(k - 1) -= bend_torque + twist_torque;
      data.damping_torque.col(k - 1) -= damper;
    } else {
      data.clamp_torque = bend_torque + twist_torque + damper;  // the vessel holds the base link with it
    }
  }
  // A clamped tip: a bend spring and damper between the last link and the tip's clamp axis, no twist
  // spring (a swivel). Written as a joint whose inboard body is the last link and outboard the clamp.
  const int last = model.links() - 1;
  const TipClamp tip = model.tipClamp();
  if (tip.active()) {
    const Eigen::Vector3d axis = links.get(&LinkBlock::u, last), clamp = data.tip_clamp_axis;
    const Eigen::Vector3d on_clamp = tip.springOnClamp(axis, clamp);
    const Eigen::Vector3d damper_on_clamp =
        tip.damperOnClamp(axis, clamp, links.get(&LinkBlock::omega, last), data.tip_clamp_omega);
    data.spring_torque.col(last) -= on_clamp;
    data.damping_torque.col(last) -= damper_on_clamp;
    data.tip_clamp_torque = -(on_clamp + damper_on_clamp);  // the clamp holds the last link with it
  }
}

/// A held joint's moment and damper on link `joint` [N m], across the two links' mean axis. The damper
/// reads the links' turning rates across their own axes (u x u'), not their spins: a spin's inertia is
/// tiny, and a damper that read it would be a stiff loop.
Eigen::Vector3d holdTorque(const JointHold& h, const ChainData& data) {
  const LinkBlocks& links = data.links;
  const Eigen::Vector3d inboard = links.get(&LinkBlock::u, h.joint - 1), outboard = links.get(&LinkBlock::u, h.joint);
  const Eigen::Vector3d direction = (inboard + outboard).normalized();
  const Eigen::Vector3d turning = outboard.cross(links.get(&LinkBlock::axis_rate, h.joint)) -
                                  inboard.cross(links.get(&LinkBlock::axis_rate, h.joint - 1));
  const Eigen::Vector3d torque = h.now - (h.fraction * h.damping) * turning;
  return torque - torque.dot(direction) * direction;
}

/// The winch's held joints' moments (ChainDeployment::jointHold) onto the links' torques: +now on link
/// `joint`, -now on link `joint - 1`.
void addJointHolds(ChainData& data) {
  for (int i = 0; i < data.deployed.jointHolds(); ++i) {
    const JointHold& h = data.deployed.jointHold(i);
    const Eigen::Vector3d torque = holdTorque(h, data);
    data.links.set(&LinkBlock::torque, h.joint, data.links.get(&LinkBlock::torque, h.joint) + torque);
    data.links.set(&LinkBlock::torque, h.joint - 1, data.links.get(&LinkBlock::torque, h.joint - 1) - torque);
  }
}

}  // namespace

void computeJointTorques(const ChainModel& model, ChainData& data, const Eigen::VectorXd& x, bool with_dampers) {
  const bool paper = model.stiffnessModel() == StiffnessModel::kPaper;
  if (paper && !model.hasSprings()) {
    // Every torque is zero since construction (the presets), but for a winch's held joints: they write
    // their moments afresh each evaluation, and the first evaluation without any clears them.
    if (data.deployed.jointHolds() == 0 && !data.holds_written) return;
    for (int k = data.deployed.firstBlock() * kBlockLanes; k < model.links(); ++k) {
      data.links.set(&LinkBlock::torque, k, Eigen::Vector3d::Zero());
    }
    addJointHolds(data);
    data.holds_written = data.deployed.jointHolds() > 0;
    return;
  }
  data.clamp_torque.setZero();
  data.tip_clamp_torque.setZero();
  data.spring_torque.setZero();
  data.damping_torque.setZero();
  if (paper) {
    paperSpringTorques(model, data, x);
  } else {
    bendingSpringTorques(model, data, x);
  }
  if (!with_dampers) data.damping_torque.setZero();
  for (int k = data.deployed.firstLink(); k < model.links(); ++k) {
    data.links.set(&LinkBlock::torque, k, data.spring_torque.col(k) + data.damping_torque.col(k));
  }
  addJointHolds(data);
}

double jointHoldPower(const ChainData& data) {
  double power = 0.0;
  for (int i = 0; i < data.deployed.jointHolds(); ++i) {
    const JointHold& h = data.deployed.jointHold(i);
    power += holdTorque(h, data).dot(data.links.get(&LinkBlock::omega, h.joint) - data.links.get(&LinkBlock::omega, h.joint - 1));
  }
  return power;
}

double damperPower(const ChainModel& model, const ChainData& data) {
  if (model.stiffnessModel() == StiffnessModel::kPaper && !model.hasSprings()) return 0.0;  // no damper at all
  double power = 0.0;
  for (int k = data.deployed.firstLink(); k < model.links(); ++k) power += data.damping_torque.col(k).dot(data.links.get(&LinkBlock::omega, k));
  return power;
}

double elasticEnergy(const ChainModel& model, ChainData& data, const Eigen::VectorXd& x) {
  const LinkProperties& p = data.deployed.properties();
  double energy = 0.0;
  if (model.stiffnessModel() == StiffnessModel::kPaper) {
    if (!model.hasSprings()) return 0.0;
    const Eigen::VectorXd& q = data.paper_q;
    paperCoordinates(model.links(), data.azimuths, x, data.paper_q, data.paper_qd);
    for (int k = 0; k < model.links(); ++k) {
      energy += 0.5 * (p.stiffness_elevation(k) * q(3 * k) * q(3 * k) +
                       p.stiffness_azimuth(k) * q(3 * k + 1) * q(3 * k + 1) +
                       p.stiffness_torsion(k) * q(3 * k + 2) * q(3 * k + 2));
    }
    return energy;
  }
  const LinkBlocks& links = data.links;
  const int first = data.deployed.firstLink();
  for (int k = first; k < model.links(); ++k) {
    const bool inner = k > first;
    const Eigen::Vector3d prev = inner ? links.get(&LinkBlock::u, k - 1) : data.clamp_axis;
    const JointGeometry g = jointGeometry(prev, links.get(&LinkBlock::u, k), x(StateLayout::twist(k)),
                                          inner ? x(StateLayout::twist(k - 1)) : data.clamp_twist);
    energy += 0.5 * p.stiffness_elevation(k) * g.bend * g.bend + 0.5 * p.stiffness_torsion(k) * g.twist * g.twist;
    if (inner && g.cosine < 0.0) energy += model.foldStop(p, k).energy(g.bend);
  }
  if (p.tip_clamp_stiffness > 0.0) energy += model.tipClamp().energy(links.get(&LinkBlock::u, model.links() - 1), data.tip_clamp_axis);
  return energy;
}

void springGeneralizedForces(const ChainModel& model, ChainData& data, const Eigen::VectorXd& x, Eigen::VectorXd& out) {
  const int n = model.links();
  const LinkProperties& p = data.deployed.properties();
  out.setZero(3 * n);
  if (model.stiffnessModel() == StiffnessModel::kPaper && !model.hasSprings()) return;
  paperCoordinates(n, data.azimuths, x, data.paper_q, data.paper_qd);
  if (model.stiffnessModel() == StiffnessModel::kPaper) {
    // The paper's springs are defined on q: dV/dq = K q (its clamp never turns).
    for (int k = 0; k < n; ++k) {
      out.segment<3>(3 * k) = Eigen::Vector3d(p.stiffness_elevation(k), p.stiffness_azimuth(k), p.stiffness_torsion(k))
                                  .cwiseProduct(data.paper_q.segment<3>(3 * k));
    }
    return;
  }
  // The spring torques tau_k by virtual power: omega_k = -psi_k' e_z - te_k' n_k - phi_k' u_k with psi, phi
  // absolute (paper_coordinates.cpp), so Q_te = -tau.n, Q_psi = -tau.e_z, Q_phi = -tau.u, and each relative
  // azimuth a_j and torsion t_j turns every link from j on: Q_a_j = sum_{k >= j} Q_psi_k (Q_t_j likewise).
  // dV/dq = -Q. Exact at the vertical too (the map from rates to omega is defined there).
  double psi = 0.0;
  for (int k = 0; k < n; ++k) {
    psi += data.paper_q(3 * k + 1);
    Eigen::Vector3d nvec, evec;
    eulerAxes(data.paper_q(3 * k), psi, nvec, evec);
    const Eigen::Vector3d tau = data.spring_torque.col(k);
    out.segment<3>(3 * k) << tau.dot(nvec), tau.z(), tau.dot(data.links.get(&LinkBlock::u, k));
  }
  for (int k = n - 2; k >= 0; --k) {
    out(3 * k + 1) += out(3 * (k + 1) + 1);
    out(3 * k + 2) += out(3 * (k + 1) + 2);
  }
}

}  // namespace cable_dynamics
