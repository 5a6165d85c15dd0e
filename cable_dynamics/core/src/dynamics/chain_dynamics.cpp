#include "cable_dynamics/dynamics/chain_dynamics.h"

#include <cassert>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "cable_dynamics/dynamics/articulated_body.h"
#include "cable_dynamics/dynamics/dense_solver.h"
#include "cable_dynamics/dynamics/energies.h"
#include "cable_dynamics/dynamics/external_loads.h"
#include "cable_dynamics/dynamics/forces/axial_spring.h"
#include "cable_dynamics/dynamics/forces/power_balance.h"
#include "cable_dynamics/dynamics/hot_path.h"
#include "cable_dynamics/dynamics/joint_torques.h"
#include "cable_dynamics/dynamics/kinematics.h"
#include "cable_dynamics/dynamics/paper_coordinates.h"
#include "cable_dynamics/dynamics/seabed_contact.h"

namespace cable_dynamics {
namespace {

/// true when every entry is finite: one vectorized sum instead of a test per entry (a NaN or an
/// infinity anywhere makes the sum NaN or infinite; so would a sum beyond 1e308, no valid state either).
template <typename Vector>
inline bool allFinite(const Vector& v) { return std::isfinite(v.sum()); }

/// After a solve: every LinkBlock::omega_rate finite (one vectorized sum; the padding lanes hold zeros).
CABLE_HOT_PATH bool finiteAngularAccelerations(const LinkBlocks& links, int first_block) {
  double sum[kBlockLanes] = {};
  for (int b = first_block; b < links.blocks(); ++b) {
    const Lanes3& rate = links.block(b).omega_rate;
    for (int i = 0; i < kBlockLanes; ++i) sum[i] += rate.x[i] + rate.y[i] + rate.z[i];
  }
  double total = 0.0;
  for (int i = 0; i < kBlockLanes; ++i) total += sum[i];
  return std::isfinite(total);
}

}  // namespace

ChainDynamics::ChainDynamics(const CableParams& params) : model_(params), data_(model_) {
  data_.current = CurrentField(params.fluid);
  // The semi-implicit integrator needs the dense workspace too: allocate it now, not inside a step.
  if (params.simulation.integrator == Integrator::kSemiImplicit) data_.dense.allocate(model_.links());
}

void ChainDynamics::followAzimuths(const Eigen::VectorXd& x) {
  cable_dynamics::followAzimuths(links(), x, data_.azimuths, data_.deployed.firstLink());
}

void ChainDynamics::placeContactAnchors(const Eigen::VectorXd& x, const EndInputs& ends, bool slide, int winch_links) {
  if (!data_.anchors.active()) return;
  forwardPass(x, ends, Stage::kKinematics);
  cable_dynamics::placeContactAnchors(model_, data_, slide, winch_links);
}

bool ChainDynamics::solve(const Eigen::VectorXd& x, const EndInputs& ends, bool all_joint_forces) {
  if (!allFinite(x.tail(StateLayout::moving(x.size(), data_.deployed.firstLink())))) return false;  // what the passes read
  forwardPass(x, ends, Stage::kLoads);
  if (model_.formulation() == Formulation::kRecursive) {
    if (!solveArticulatedBody(model_, data_, all_joint_forces)) return false;
  } else {
    if (!solveDense(model_, data_)) return false;  // its workspace: allocated by ChainData for this formulation
  }
  if (!finiteAngularAccelerations(data_.links, data_.deployed.firstBlock())) return false;
  // What the base (through the force it holds the base link's end with), the coupling, the clamps and a
  // winch's paid-out cable put in.
  data_.input_power = endsInputPower(model_, data_, ends, data_.joint_force.col(data_.deployed.firstLink()));
  return true;
}

bool ChainDynamics::holdNewJoint(int joint, const Eigen::VectorXd& x, const EndInputs& ends, double span,
                                 double damping_rate) {
  // The held moment acts across the links' axis u (they are straight at the split; a spin passes no
  // moment through a joint). The relative angular acceleration across u is affine in it: its value at
  // zero and its change per unit moment about two axes e1, e2 across u give the moment that makes it zero.
  const Eigen::Vector3d axis = data_.links.get(&LinkBlock::u, joint).normalized();
  const Eigen::Vector3d e1 = axis.unitOrthogonal(), e2 = axis.cross(e1);
  const auto relative = [&](const Eigen::Vector3d& torque, Eigen::Vector2d& out) {
    data_.deployed.holdJoint(joint, torque, 0.0, ends.time, ends.winch_deployed, span);
    if (!solve(x, ends, false)) return false;
    const Eigen::Vector3d a =
        data_.links.get(&LinkBlock::omega_rate, joint) - data_.links.get(&LinkBlock::omega_rate, joint - 1);
    out << e1.dot(a), e2.dot(a);
    return true;
  };
  Eigen::Vector2d free = Eigen::Vector2d::Zero(), unit = Eigen::Vector2d::Zero();  // read even when a probe fails
  Eigen::Matrix2d response;
  bool ok = relative(Eigen::Vector3d::Zero(), free) && relative(e1, unit);
  response.col(0) = unit - free;
  ok = ok && relative(e2, unit);
  response.col(1) = unit - free;
  const Eigen::Vector2d moment = ok ? Eigen::Vector2d(response.fullPivLu().solve(-free)) : Eigen::Vector2d::Zero();
  const Eigen::Vector3d held = moment(0) * e1 + moment(1) * e2;
  // The joint's relative inertia across u is the inverse of its response (symmetric up to round-off);
  // the damper takes the smaller of its two values.
  const Eigen::Matrix2d inverse = ok ? Eigen::Matrix2d(response.inverse()) : Eigen::Matrix2d::Zero();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(0.5 * (inverse + inverse.transpose()), Eigen::EigenvaluesOnly);
  const double across = eigen.eigenvalues()(0);
  ok = ok && held.allFinite() && std::isfinite(across) && across > 0.0;
  data_.deployed.holdJoint(joint, ok ? held : Eigen::Vector3d::Zero(), ok ? damping_rate * across : 0.0, ends.time,
                   ends.winch_deployed, span);  // a failed probe holds nothing
  return ok;
}

void ChainDynamics::computeBodyTerms(const Eigen::VectorXd& x, const EndInputs& ends) {
  if (!model_.body().active) return;
  const int n = links();
  computeRovBodyTerms(model_.body(), x.segment<4>(StateLayout::bodyAttitude(n)), x.segment<3>(StateLayout::bodyOmega(n)),
                      data_.tip_velocity, data_.current.at(data_.tip_position.z()), ends.body_thrust, data_.body);
}

void ChainDynamics::applyEnds(const EndInputs& ends) {
  if (ends.winch) model_.setWinchLinkLength(data_.deployed, ends.winch_length);
  if (data_.deployed.jointHolds() > 0) data_.deployed.setHoldState(ends.time, ends.winch_deployed);
  const LinkProperties& p = model_.configured();  // the clamps at rest: the same for any deployment
  data_.clamp_axis = ends.clamp_moves ? ends.clamp_axis : p.clamp_axis;
  data_.clamp_twist = ends.clamp_moves ? ends.clamp_twist : p.clamp_twist;
  data_.clamp_omega = ends.clamp_moves ? ends.clamp_omega : Eigen::Vector3d::Zero();
  data_.tip_clamp_axis = ends.tip_clamp_moves ? ends.tip_clamp_axis : p.tip_clamp_axis;
  data_.tip_clamp_omega = ends.tip_clamp_moves ? ends.tip_clamp_omega : Eigen::Vector3d::Zero();
}

bool ChainDynamics::derivative(const Eigen::VectorXd& x, const EndInputs& ends, Eigen::VectorXd& xdot) {
  assert(x.size() == stateSize() && xdot.size() == stateSize());
  if (!solve(x, ends, false)) return false;
  writeRates(xdot);
  return true;
}

CABLE_HOT_PATH void ChainDynamics::writeRates(Eigen::VectorXd& xdot) const {
  const int n = links(), first = data_.deployed.firstLink();
  // The drum's slots (a winch) stay as they are: their rates are zero. Slots leave the cable one at a
  // time, each at a step's end, so only the last one stowed may still hold rates in this buffer.
  if (first > 0) xdot.segment<StateLayout::kPerLink>(StateLayout::axis(first - 1)).setZero();
  for (int k = first; k < n; ++k) {
    const LinkBlock& block = data_.links.of(k);
    const int i = LinkBlocks::lane(k);
    xdot.segment<3>(StateLayout::axis(k)) << block.axis_rate.x[i], block.axis_rate.y[i], block.axis_rate.z[i];
    xdot(StateLayout::twist(k)) = block.twist_rate[i];
    xdot.segment<3>(StateLayout::omega(k)) << block.omega_rate.x[i], block.omega_rate.y[i], block.omega_rate.z[i];
  }
  xdot(StateLayout::dissipated(n)) =
      -lossPower(model_, data_, data_.added_mass_power, data_.contact_dissipation, axialLoss(model_, data_));
  xdot(StateLayout::workInput(n)) = data_.input_power;
  const bool body = model_.body().active;
  if (body) {
    const RovBodyTerms& terms = data_.body;
    xdot.segment<4>(StateLayout::bodyAttitude(n)) = attitudeRate(terms.attitude, terms.omega);
    xdot.segment<3>(StateLayout::bodyOmega(n)) = terms.acceleration.tail<3>();
  }
  if (model_.axial()) {
    if (first > 0) {  // the stretches sit in the moving tail: the last slot stowed keeps its zeros
      xdot(StateLayout::stretch(n, body, first - 1)) = 0.0;
      xdot(StateLayout::stretchRate(n, body, first - 1)) = 0.0;
    }
    for (int k = first; k < n; ++k) {
      const LinkBlock& block = data_.links.of(k);
      const int i = LinkBlocks::lane(k);
      xdot(StateLayout::stretch(n, body, k)) = block.stretch_rate[i];
      xdot(StateLayout::stretchRate(n, body, k)) = block.stretch_acc[i];
    }
  }
}

bool ChainDynamics::evaluate(const Eigen::VectorXd& x, const EndInputs& ends, ChainOutputs& out) {
  if (!solve(x, ends, true)) return false;
  const int n = links(), first = data_.deployed.firstLink();
  const LinkBlocks& l = data_.links;
  out.omega_rate.setZero(3 * n);  // the drum's slots stay at rest
  for (int k = first; k < n; ++k) out.omega_rate.segment<3>(3 * k) = l.get(&LinkBlock::omega_rate, k);
  out.ends.resize(3, n + 1);
  for (int k = 0; k < first; ++k) out.ends.col(k) = l.get(&LinkBlock::base_pos, first);  // the drum's, at the base
  for (int k = first; k < n; ++k) out.ends.col(k) = l.get(&LinkBlock::base_pos, k);
  out.ends.col(n) = data_.tip_position;
  out.joint_force = data_.joint_force;
  springGeneralizedForces(model_, data_, x, out.spring_force);
  out.tension.resize(n);
  out.tension.setZero();
  for (int k = first; k < n; ++k) out.tension(k) = -data_.joint_force.col(k).dot(l.get(&LinkBlock::u, k));
  out.slack_links = 0;
  if (model_.axial()) {
    out.stretch.setZero(n);
    out.far_tension.setZero(n);
    out.strain.setZero(n);
    for (int k = first; k < n; ++k) {
      const double s = l.get(&LinkBlock::stretch, k);
      out.stretch(k) = s;
      out.far_tension(k) = l.get(&LinkBlock::axial_tension, k);
      out.strain(k) = s / data_.deployed.get(&LinkConstants::length, k);
      const bool locked = model_.stretchLocked(k);
      if (!locked && s < 0.0) ++out.slack_links;
    }
  } else {
    out.stretch.resize(0);
    out.far_tension.resize(0);
    out.strain.resize(0);
  }
  out.load_force = data_.load_force;
  out.base_force = -data_.joint_force.col(first);
  out.coupling_force = data_.coupling;
  kineticAndPotentialEnergy(model_, data_, out.kinetic_energy, out.potential_energy);
  out.elastic_energy = elasticEnergy(model_, data_, x) + axialEnergy(model_, data_);
  out.contact_energy = 0.0;
  if (model_.seabedContact().enabled()) {
    reportSeabedContact(model_, data_, out.seabed);
    out.contact_energy = out.seabed.energy;
  }
  reportLimits(model_, data_, out.tension, out.load_force, model_.seabedContact().enabled() ? &out.seabed : nullptr,
               out.limits);
  return true;
}

bool ChainDynamics::matchTipVelocity(Eigen::VectorXd& x, const EndInputs& ends) {
  computeLoads(x, ends);
  const Eigen::Vector3d change = ends.target_velocity - data_.tip_velocity;
  if (!(change.norm() > 0.0)) return change.allFinite();
  Eigen::Matrix3Xd omega_change;
  Eigen::VectorXd stretch_rate_change;
  if (!tipVelocityProjection(model_, data_, change, omega_change, stretch_rate_change)) return false;
  const int n = links();
  const bool body = model_.body().active;
  for (int k = data_.deployed.firstLink(); k < n; ++k) {
    x.segment<3>(StateLayout::omega(k)) += omega_change.col(k);
    if (model_.axial()) x(StateLayout::stretchRate(n, body, k)) += stretch_rate_change(k);
  }
  return true;
}

void ChainDynamics::forwardPass(const Eigen::VectorXd& x, const EndInputs& ends, Stage stage, bool with_dampers) {
  applyEnds(ends);
  computeAxialTensions(model_, data_, x, ends.winch ? ends.winch_speed : 0.0);  // the kinematics read them
  computeKinematics(model_, data_, x, ends);
  computeBodyTerms(x, ends);
  if (stage == Stage::kKinematics) return;
  computeExternalLoads(model_, data_, ends);
  computeJointTorques(model_, data_, x, with_dampers);
}

void ChainDynamics::computeLoads(const Eigen::VectorXd& x, const EndInputs& ends) {
  forwardPass(x, ends, Stage::kLoads);
}

double ChainDynamics::mechanicalEnergy(const Eigen::VectorXd& x, const EndInputs& ends, double& magnitude) {
  forwardPass(x, ends, Stage::kKinematics);
  return solvedMechanicalEnergy(x, magnitude);
}

void ChainDynamics::computeBodyPose(const Eigen::VectorXd& x, const EndInputs& ends) {
  forwardPass(x, ends, Stage::kKinematics);
}

double ChainDynamics::solvedMechanicalEnergy(const Eigen::VectorXd& x, double& magnitude) {
  double kinetic = 0.0, potential = 0.0;
  kineticAndPotentialEnergy(model_, data_, kinetic, potential);
  const double elastic = elasticEnergy(model_, data_, x) + axialEnergy(model_, data_);
  const double contact = seabedContactEnergy(model_, data_);
  magnitude = std::abs(kinetic) + std::abs(potential) + std::abs(elastic) + contact;
  return kinetic + potential + elastic + contact;
}

void ChainDynamics::generalizedForces(const Eigen::VectorXd& x, const EndInputs& ends, bool with_dampers,
                                      Eigen::VectorXd& out) {
  data_.dense.allocate(links());  // a no-op after construction with the semi-implicit integrator
  forwardPass(x, ends, Stage::kLoads, with_dampers);  // with an ROV body's terms, which the dense forces read
  assembleGeneralizedForces(model_, data_);
  out = data_.dense.rhs;
}

const Eigen::MatrixXd& ChainDynamics::massMatrix() {
  assembleMassMatrix(model_, data_);
  return data_.dense.mass_matrix;
}

void ChainDynamics::paperCoordinates(const Eigen::VectorXd& x, Eigen::VectorXd& q, Eigen::VectorXd& qd) const {
  cable_dynamics::paperCoordinates(links(), data_.azimuths, x, q, qd);
}

void ChainDynamics::stateFromPaper(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, Eigen::VectorXd& x) const {
  cable_dynamics::stateFromPaper(links(), q, qd, x);
  if (model_.axial() && !model_.body().active) {
    x.conservativeResize(stateSize());
    x.tail(2 * links()).setZero();  // unstretched, at rest
  }
  if (!model_.body().active) return;
  // An ROV body starts at rest in its configured attitude (load.body.initial_attitude; level: the
  // quaternion (0, 1, 0, 0), the half turn about x between its frame, z up, and the paper frame, z down).
  x.conservativeResize(stateSize());
  if (model_.axial()) x.tail(2 * links()).setZero();  // unstretched, at rest
  x.segment<4>(StateLayout::bodyAttitude(links())) = model_.body().initial_attitude;
  x.segment<3>(StateLayout::bodyOmega(links())).setZero();
}

}  // namespace cable_dynamics
