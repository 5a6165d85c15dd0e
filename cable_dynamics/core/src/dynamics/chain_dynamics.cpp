#include "cable_dynamics/dynamics/chain_dynamics.h"

#include <cassert>
#include <cmath>

#include <Eigen/Geometry>

#include "cable_dynamics/dynamics/hot_path.h"
#include "cable_dynamics/dynamics/paper_model.h"

namespace cable_dynamics {
namespace {

const Eigen::Vector3d kDown = Eigen::Vector3d::UnitZ();

/// Below this sin(te) a link counts as hanging straight down: its azimuth is not defined there.
constexpr double kVerticalSine = 1e-9;

inline Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return s;
}

/// beta / sin(beta) for the bend angle beta, with its series where sin(beta) -> 0.
inline double angleOverSine(double beta, double sine) {
  return beta < 1e-4 ? 1.0 + beta * beta / 6.0 : beta / sine;
}

/// true when every entry is finite: one vectorized sum instead of a test per entry (a NaN or an
/// infinity anywhere makes the sum NaN or infinite; so would a sum beyond 1e308, no valid state either).
inline bool allFinite(const Eigen::VectorXd& v) { return std::isfinite(v.sum()); }

inline double wrapToPi(double a) { return std::atan2(std::sin(a), std::cos(a)); }

/// Geometry of the bending model's joint between axes `prev` and `axis` with vertical twists sigma_prev
/// and sigma: the bend angle and the twist after parallel transport, tau = sigma - sigma_prev - Omega,
/// Omega the solid angle of the spherical triangle (down, prev, axis) (docs/MODEL.md section 5).
struct JointGeometry {
  Eigen::Vector3d cross;  ///< prev x axis
  double cosine, sine;    ///< of the bend angle
  double bend, twist;     ///< [rad]
};

inline JointGeometry jointGeometry(const Eigen::Vector3d& prev, const Eigen::Vector3d& axis, double sigma,
                                   double sigma_prev) {
  JointGeometry g;
  g.cross = prev.cross(axis);
  g.cosine = prev.dot(axis);
  g.sine = g.cross.norm();
  g.bend = std::atan2(g.sine, g.cosine);
  const double holonomy = -2.0 * std::atan2(kDown.dot(g.cross), 1.0 + prev.z() + axis.z() + g.cosine);
  g.twist = sigma - sigma_prev - holonomy;
  return g;
}

/// Unit vectors of the paper's Euler angles for a link at elevation te and azimuth psi:
/// n = (cos psi, -sin psi, 0) (the elevation axis, up to sign), e = du/dte.
inline void eulerAxes(double te, double psi, Eigen::Vector3d& n, Eigen::Vector3d& e) {
  n << std::cos(psi), -std::sin(psi), 0.0;
  e << std::cos(te) * std::sin(psi), std::cos(te) * std::cos(psi), -std::sin(te);
}

}  // namespace

ChainDynamics::ChainDynamics(const CableParams& params)
    : n_(params.links),
      props_(deriveLinkProperties(params)),
      stiffness_model_(params.stiffness.model),
      current_(params.fluid),
      density_(params.fluid.density),
      diameter_(params.diameter),
      drag_(params.fluid, params.diameter),
      load_drag_area_(params.load.drag_area),
      load_coupling_stiffness_(params.load.coupling_stiffness),
      load_coupling_damping_(params.load.coupling_damping),
      azimuths_(params.links) {
  const int n = n_;
  const double radius = 0.5 * diameter_;
  load_inertia_ = props_.load_mass + params.load.added_mass;
  load_weight_ = props_.gravity * props_.load_submerged_mass;
  paper_psi_ = Eigen::VectorXd::Zero(n);

  for (Eigen::Matrix3Xd* m : {&inertial_force_, &inertial_moment_, &axis_acc_, &joint_force_, &damping_torque_,
                              &spring_torque_, &link_base_acc_}) {
    m->setZero(3, n);
  }
  tensor_.assign(n, Eigen::Matrix3d::Zero());
  outboard_.assign(n, Eigen::Matrix3d::Zero());
  column_.assign(n, Eigen::Matrix3d::Zero());
  for (Eigen::VectorXd* v : {&force_plus_, &force_minus_, &velocity_, &step_rhs_, &delta_}) v->setZero(3 * n);
  perturbed_.setZero(StateLayout::size(n));
  recursive_ = params.simulation.formulation == "recursive";
  has_springs_ = props_.stiffness_elevation.any() || props_.stiffness_azimuth.any() || props_.stiffness_torsion.any() ||
                 props_.damping_elevation.any() || props_.damping_azimuth.any() || props_.damping_torsion.any();
  fillLinkConstants(params.fluid.added_mass * density_ * M_PI * radius * radius, radius);
  paper_q_.setZero(3 * n);
  paper_qd_.setZero(3 * n);
  rhs_.setZero(3 * n);
  if (!recursive_ || params.simulation.integrator == "semi_implicit") allocateDense();
}

void ChainDynamics::fillLinkConstants(double added_per_length, double radius) {
  links_ = LinkBlocks(n_);
  for (int b = 0; b < links_.blocks(); ++b) {
    LinkBlock& block = links_.block(b);
    for (int i = 0; i < kBlockLanes; ++i) {
      block.u.set(i, {0.0, 0.0, 1.0});  // the padding lanes: a unit axis keeps them finite
      const int k = b * kBlockLanes + i;
      if (k >= n_) continue;  // zero length and mass: adds nothing anywhere
      const double l = props_.length(k);
      block.length[i] = l;
      block.mass_per_length[i] = props_.mass(k) / l;
      block.added[i] = added_per_length;
      block.across[i] = block.mass_per_length[i] + added_per_length;
      block.weight[i] = props_.gravity * props_.submerged_mass(k);
      block.half_moment[i] = 0.5 * l * l * block.across[i];
      block.third_moment[i] = l * l * l / 3.0 * block.across[i];
      // The translation integral over the link already holds m l^2/12; the rest of I_T is the thickness.
      block.thick_transverse[i] = props_.mass(k) * (radius * radius / 4.0);
      block.own_transverse[i] = block.third_moment[i] + block.thick_transverse[i];
      block.polar[i] = props_.inertia_polar(k);
      block.inverse_polar[i] = 1.0 / props_.inertia_polar(k);
    }
  }
}

CABLE_HOT_PATH void ChainDynamics::kinematics(const Eigen::VectorXd& x, const EndInputs& ends) {
  // Three passes, each over the whole chain. The state holds a link's numbers together and a block
  // holds them by kind, so the first pass copies them one by one; a whole pass lies between those
  // scalar stores and the vector loads of the second (a vector load right after the scalar stores
  // it spans would wait for them to reach the cache).
  for (int k = 0; k < n_; ++k) {
    LinkBlock& block = links_.of(k);
    const int i = LinkBlocks::lane(k);
    const double* link = x.data() + StateLayout::axis(k);
    block.u.set(i, {link[0], link[1], link[2]});
    block.omega.set(i, {link[4], link[5], link[6]});
  }
  for (int b = 0; b < links_.blocks(); ++b) {
    LinkBlock& block = links_.block(b);
    for (int i = 0; i < kBlockLanes; ++i) {
      // Links are unit vectors up to the integrator's drift: use the normalized axis.
      const Vec3 raw = block.u[i], omega = block.omega[i];
      const Vec3 axis = (1.0 / std::sqrt(dot(raw, raw))) * raw;
      const Vec3 axis_rate = cross(omega, axis);
      block.u.set(i, axis);
      block.axis_rate.set(i, axis_rate);
      block.beta.set(i, cross(omega, axis_rate));  // centripetal part of u''
      // sigma = psi + phi: from omega = -psi' e_z - te' n - phi' u, omega.(e_z + u) = -(psi' + phi')(1 + cos te).
      const double denominator = 1.0 + axis.z, spin = dot(omega, axis);
      block.twist_rate[i] = denominator > 1e-12 ? -(omega.z + spin) / denominator : -spin;
    }
  }
  // Base ends: running sums along the chain.
  Vec3 pos = toVec3(ends.base_position), vel = toVec3(ends.base_velocity), acc = toVec3(ends.base_acceleration);
  for (int k = 0; k < n_; ++k) {
    LinkBlock& block = links_.of(k);
    const int i = LinkBlocks::lane(k);
    block.base_pos.set(i, pos);
    block.base_vel.set(i, vel);
    block.known_acc.set(i, acc);
    const double l = block.length[i];
    pos = pos + l * block.u[i];
    vel = vel + l * block.axis_rate[i];
    acc = acc + l * block.beta[i];
  }
  tip_pos_ = toEigen(pos);
  tip_vel_ = toEigen(vel);
  tip_known_acc_ = toEigen(acc);
}

CABLE_HOT_PATH void ChainDynamics::externalForces(const EndInputs& ends) {
  drag_power_ = 0.0;
  const bool uniform = current_.uniform();
  const Vec3 current = toVec3(current_.uniformValue());
  for (int b = 0; b < links_.blocks(); ++b) {
    LinkBlock& block = links_.block(b);
    // Submerged weight, uniform along the link: total and first moment about the base end.
    for (int i = 0; i < kBlockLanes; ++i) {
      block.force.set(i, {0.0, 0.0, block.weight[i]});
      block.moment.set(i, {0.0, 0.0, 0.5 * block.length[i] * block.weight[i]});
    }
    if (density_ <= 0.0) continue;
    if (uniform) {
      drag_.addUniform(current, block);
    } else {
      const int first = b * kBlockLanes, count = std::min(kBlockLanes, n_ - first);
      for (int i = 0; i < count; ++i) {
        Eigen::Vector3d fd, md;
        drag_.pointwise(current_, block.length[i], toEigen(block.base_pos[i]), toEigen(block.base_vel[i]),
                        toEigen(block.u[i]), toEigen(block.axis_rate[i]), fd, md);
        block.force.set(i, block.force[i] + toVec3(fd));
        block.moment.set(i, block.moment[i] + toVec3(md));
        block.drag_power[i] = fd.dot(toEigen(block.base_vel[i])) + md.dot(toEigen(block.axis_rate[i]));
      }
    }
    double power = 0.0;  // the padding lanes' drag is zero (zero length)
    for (int i = 0; i < kBlockLanes; ++i) power += block.drag_power[i];
    drag_power_ += power;
  }
  // The load: weight, drag, and the PD coupling to its anchor or to the ROV.
  load_external_ = load_weight_ * kDown;
  if (density_ > 0.0 && load_drag_area_ > 0.0) {
    const Eigen::Vector3d relative = current_.at(tip_pos_.z()) - tip_vel_;
    const Eigen::Vector3d drag = 0.5 * density_ * load_drag_area_ * relative.norm() * relative;
    load_external_ += drag;
    drag_power_ += drag.dot(tip_vel_);
  }
  coupling_.setZero();
  if (ends.load_coupled) {
    coupling_ = -load_coupling_stiffness_ * (tip_pos_ - ends.target_position) -
                load_coupling_damping_ * (tip_vel_ - ends.target_velocity);
    load_external_ += coupling_;
  }
}

void ChainDynamics::inertiaTensors() {
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  for (int k = 0; k < n_; ++k) {
    const Eigen::Vector3d axis = links_.get(&LinkBlock::u, k);
    tensor_[k] = links_.get(&LinkBlock::mass_per_length, k) * identity +
                 links_.get(&LinkBlock::added, k) * (identity - axis * axis.transpose());
  }
}

void ChainDynamics::assembleForces() {
  const int n = n_;
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  inertiaTensors();
  // Outboard inertia B_k = sum_{j>k} l_j A_j + load, and the known-acceleration (bias) integrals.
  Eigen::Matrix3d outboard = load_inertia_ * identity;
  Eigen::Vector3d outboard_force = load_external_ - load_inertia_ * tip_known_acc_;
  for (int k = n - 1; k >= 0; --k) {
    outboard_[k] = outboard;
    const double l = props_.length(k);
    const Eigen::Matrix3d& a = tensor_[k];
    const Eigen::Vector3d known = links_.get(&LinkBlock::known_acc, k), beta = links_.get(&LinkBlock::beta, k);
    inertial_force_.col(k) = a * (l * known + 0.5 * l * l * beta);
    inertial_moment_.col(k) = a * (0.5 * l * l * known + (l * l * l / 3.0) * beta);
    // Generalized force of link k's angular velocity: moment about joint k of everything outboard of it.
    const Eigen::Vector3d lever = l * outboard_force + links_.get(&LinkBlock::moment, k) - inertial_moment_.col(k);
    const Eigen::Vector3d omega = links_.get(&LinkBlock::omega, k), axis = links_.get(&LinkBlock::u, k);
    const double ip = props_.inertia_polar(k), it = links_.get(&LinkBlock::thick_transverse, k);
    const Eigen::Vector3d spin_axis = axis * axis.dot(omega);
    const Eigen::Vector3d angular_momentum = it * (omega - spin_axis) + ip * spin_axis;
    rhs_.segment<3>(3 * k) = axis.cross(lever) + links_.get(&LinkBlock::torque, k) - omega.cross(angular_momentum);
    outboard_force += links_.get(&LinkBlock::force, k) - inertial_force_.col(k);
    outboard += l * a;
  }
}

void ChainDynamics::assembleMass() {
  const int n = n_;
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  // M_rj = -l_r [u_r]x E_j [u_j]x for r < j with E_j = l_j (l_j/2 A_j + B_j); diagonal blocks use
  // l_j^2 (l_j/3 A_j + B_j) plus the thickness inertia of the link.
  for (int j = 0; j < n; ++j) {
    const double l = props_.length(j);
    const Eigen::Matrix3d uj = skew(links_.get(&LinkBlock::u, j));
    column_[j] = (l * (0.5 * l * tensor_[j] + outboard_[j])) * uj;
    const Eigen::Matrix3d diagonal = -uj * ((l * l) * ((l / 3.0) * tensor_[j] + outboard_[j])) * uj;
    const Eigen::Vector3d axis = links_.get(&LinkBlock::u, j);
    const Eigen::Matrix3d rotation_inertia =
        links_.get(&LinkBlock::thick_transverse, j) * (identity - axis * axis.transpose()) +
        props_.inertia_polar(j) * axis * axis.transpose();
    mass_matrix_.block<3, 3>(3 * j, 3 * j) = diagonal + rotation_inertia;
    for (int r = 0; r < j; ++r) {
      const Eigen::Matrix3d block = -props_.length(r) * skew(links_.get(&LinkBlock::u, r)) * column_[j];
      mass_matrix_.block<3, 3>(3 * r, 3 * j) = block;
      mass_matrix_.block<3, 3>(3 * j, 3 * r) = block.transpose();
    }
  }
}

void ChainDynamics::jointForces() {
  // Accelerations of the link axes and base ends with the solved angular accelerations, then the force
  // on everything outboard of each joint from Newton's law for that part: J_k = sum (A a - f).
  Eigen::Vector3d acc = links_.get(&LinkBlock::known_acc, 0);  // the base's own acceleration
  Eigen::Matrix3Xd& link_base_acc = link_base_acc_;
  for (int k = 0; k < n_; ++k) {
    axis_acc_.col(k) = rhs_.segment<3>(3 * k).cross(links_.get(&LinkBlock::u, k)) + links_.get(&LinkBlock::beta, k);
    link_base_acc.col(k) = acc;
    acc += props_.length(k) * axis_acc_.col(k);
  }
  const Eigen::Vector3d tip_acc = acc;
  load_force_ = load_inertia_ * tip_acc - load_external_;
  Eigen::Vector3d outboard = load_force_;
  added_mass_power_ = 0.0;
  for (int k = n_ - 1; k >= 0; --k) {
    const double l = props_.length(k);
    const Eigen::Vector3d mean_acc = l * link_base_acc.col(k) + 0.5 * l * l * axis_acc_.col(k);
    outboard += tensor_[k] * mean_acc - links_.get(&LinkBlock::force, k);
    joint_force_.col(k) = outboard;
    added_mass_power_ += addedMassPower(k, link_base_acc.col(k), axis_acc_.col(k));
  }
}

double ChainDynamics::addedMassPower(int k, const Eigen::Vector3d& base_acc, const Eigen::Vector3d& axis_acc) const {
  const LinkBlock& block = links_.of(k);
  const int i = LinkBlocks::lane(k);
  Vec3 base_weight, axis_weight;
  addedMassPowerWeights(block.added[i], block.length[i], block.u[i], block.axis_rate[i], block.base_vel[i],
                        base_weight, axis_weight);
  return dot(base_weight, toVec3(base_acc)) + dot(axis_weight, toVec3(axis_acc));
}

bool ChainDynamics::solve(const Eigen::VectorXd& x, const EndInputs& ends, bool all_joint_forces) {
  if (!allFinite(x)) return false;
  kinematics(x, ends);
  externalForces(ends);
  computeJointTorques(x);
  if (recursive_) {
    solveRecursive(all_joint_forces);  // LinkBlock::omega_rate holds the angular accelerations
  } else {
    assembleForces();
    assembleMass();
    llt_.compute(mass_matrix_);
    if (llt_.info() != Eigen::Success) return false;
    llt_.solveInPlace(rhs_);  // rhs_ now holds the angular accelerations
    jointForces();
    for (int k = 0; k < n_; ++k) links_.set(&LinkBlock::omega_rate, k, rhs_.segment<3>(3 * k));
  }
  if (!finiteAngularAccelerations()) return false;
  input_power_ = joint_force_.col(0).dot(ends.base_velocity) + coupling_.dot(tip_vel_);
  return true;
}

CABLE_HOT_PATH bool ChainDynamics::finiteAngularAccelerations() const {
  // One vectorized sum (see allFinite); the padding lanes hold zeros.
  double sum[kBlockLanes] = {};
  for (int b = 0; b < links_.blocks(); ++b) {
    const Lanes3& rate = links_.block(b).omega_rate;
    for (int i = 0; i < kBlockLanes; ++i) sum[i] += rate.x[i] + rate.y[i] + rate.z[i];
  }
  double total = 0.0;
  for (int i = 0; i < kBlockLanes; ++i) total += sum[i];
  return std::isfinite(total);
}

bool ChainDynamics::derivative(const Eigen::VectorXd& x, const EndInputs& ends, Eigen::VectorXd& xdot) {
  assert(x.size() == stateSize() && xdot.size() == stateSize());
  if (!solve(x, ends, false)) return false;
  writeRates(xdot);
  return true;
}

CABLE_HOT_PATH void ChainDynamics::writeRates(Eigen::VectorXd& xdot) const {
  for (int k = 0; k < n_; ++k) {
    const LinkBlock& block = links_.of(k);
    const int i = LinkBlocks::lane(k);
    xdot.segment<3>(StateLayout::axis(k)) << block.axis_rate.x[i], block.axis_rate.y[i], block.axis_rate.z[i];
    xdot(StateLayout::twist(k)) = block.twist_rate[i];
    xdot.segment<3>(StateLayout::omega(k)) << block.omega_rate.x[i], block.omega_rate.y[i], block.omega_rate.z[i];
  }
  double damping_power = 0.0;
  if (stiffness_model_ != StiffnessModel::kPaper || has_springs_) {  // otherwise no damper at all
    for (int k = 0; k < n_; ++k) damping_power += damping_torque_.col(k).dot(links_.get(&LinkBlock::omega, k));
  }
  xdot(StateLayout::dissipated(n_)) = -(drag_power_ + added_mass_power_ + damping_power);
  xdot(StateLayout::workInput(n_)) = input_power_;
}

bool ChainDynamics::evaluate(const Eigen::VectorXd& x, const EndInputs& ends, ChainOutputs& out) {
  if (!solve(x, ends, true)) return false;
  const int n = n_;
  out.omega_rate.resize(3 * n);
  for (int k = 0; k < n; ++k) out.omega_rate.segment<3>(3 * k) = links_.get(&LinkBlock::omega_rate, k);
  out.ends.resize(3, n + 1);
  for (int k = 0; k < n; ++k) out.ends.col(k) = links_.get(&LinkBlock::base_pos, k);
  out.ends.col(n) = tip_pos_;
  out.joint_force = joint_force_;
  out.tension.resize(n);
  for (int k = 0; k < n; ++k) out.tension(k) = -joint_force_.col(k).dot(links_.get(&LinkBlock::u, k));
  out.load_force = load_force_;
  out.base_force = -joint_force_.col(0);
  out.coupling_force = coupling_;
  double kinetic = 0.0, potential = 0.0;
  kineticAndPotential(kinetic, potential);
  out.kinetic_energy = kinetic;
  out.potential_energy = potential;
  out.elastic_energy = elasticEnergy(x);
  return true;
}

void ChainDynamics::generalizedForces(const Eigen::VectorXd& x, const EndInputs& ends, Eigen::VectorXd& out) {
  kinematics(x, ends);
  externalForces(ends);
  computeJointTorques(x);
  assembleForces();
  out = rhs_;
}

void ChainDynamics::setRecursive(bool recursive) {
  recursive_ = recursive;
  if (!recursive) allocateDense();
}

void ChainDynamics::allocateDense() {
  // Five 3n x 3n matrices: 360 MB at n = 1000, which the recursive formulation with RK4 never touches.
  const int dof = 3 * n_;
  if (mass_matrix_.rows() == dof) return;
  for (Eigen::MatrixXd* m : {&mass_matrix_, &jacobian_velocity_, &jacobian_rotation_, &system_}) m->setZero(dof, dof);
  lu_ = Eigen::PartialPivLU<Eigen::MatrixXd>(dof);
  llt_ = Eigen::LLT<Eigen::MatrixXd>(dof);
}

bool ChainDynamics::semiImplicitStep(const Eigen::VectorXd& x, const EndInputs& ends, double h, Eigen::VectorXd& next) {
  allocateDense();  // a no-op unless the configuration asked for neither the dense formulation nor this integrator
  assert(x.size() == stateSize() && next.size() == stateSize());
  if (!x.allFinite()) return false;
  const int n = n_, dof = 3 * n;
  // Jacobians of the generalized forces (external, springs, dampers and the velocity terms) with respect
  // to the angular velocities and to small rotations of each link, by central differences. Each column
  // costs one O(n) force evaluation, O(n^2) in all: cheaper than the O(n^3) solve below.
  const double eps = 1e-6;
  perturbed_ = x;
  for (int j = 0; j < dof; ++j) {
    const int index = StateLayout::omega(j / 3) + j % 3;
    perturbed_(index) = x(index) + eps;
    generalizedForces(perturbed_, ends, force_plus_);
    perturbed_(index) = x(index) - eps;
    generalizedForces(perturbed_, ends, force_minus_);
    perturbed_(index) = x(index);
    jacobian_velocity_.col(j) = (force_plus_ - force_minus_) / (2.0 * eps);
  }
  // The rotation Jacobian is the stiffness: it leaves the dampers out. (The paper's elevation damper
  // turns with the azimuth, which is ill-conditioned near the vertical; its rate Jacobian above is not.)
  skip_damping_ = true;
  for (int j = 0; j < dof; ++j) {
    const int k = j / 3;
    const Eigen::Vector3d axis = x.segment<3>(StateLayout::axis(k)).normalized();
    const Eigen::Vector3d turn = Eigen::Vector3d::Unit(j % 3);
    // A rotation by e about `turn` moves u by e turn x u and sigma by -e turn.(e_z + u)/(1 + u_z).
    const double twist_rate = 1.0 + axis.z() > 1e-12 ? -turn.dot(kDown + axis) / (1.0 + axis.z()) : -turn.dot(axis);
    for (const double sign : {1.0, -1.0}) {
      perturbed_.segment<3>(StateLayout::axis(k)) = (axis + sign * eps * turn.cross(axis)).normalized();
      perturbed_(StateLayout::twist(k)) = x(StateLayout::twist(k)) + sign * eps * twist_rate;
      generalizedForces(perturbed_, ends, sign > 0 ? force_plus_ : force_minus_);
    }
    perturbed_.segment<3>(StateLayout::axis(k)) = x.segment<3>(StateLayout::axis(k));
    perturbed_(StateLayout::twist(k)) = x(StateLayout::twist(k));
    jacobian_rotation_.col(j) = (force_plus_ - force_minus_) / (2.0 * eps);
  }
  skip_damping_ = false;
  // Linearized backward Euler in the velocities: M dw = h (Q(x_n) + K_r h (w_n + dw) + K_w dw), with
  // K_r, K_w the Jacobians above, then the orientations advance with the new velocities.
  generalizedForces(x, ends, force_plus_);
  assembleMass();
  system_ = mass_matrix_ - h * jacobian_velocity_ - (h * h) * jacobian_rotation_;
  for (int k = 0; k < n; ++k) velocity_.segment<3>(3 * k) = links_.get(&LinkBlock::omega, k);
  step_rhs_.noalias() = jacobian_rotation_ * velocity_;
  step_rhs_ = h * (force_plus_ + h * step_rhs_);
  lu_.compute(system_);
  delta_.noalias() = lu_.solve(step_rhs_);
  if (!delta_.allFinite()) return false;
  // Forces along the cable and the powers, with the step's mean angular acceleration.
  rhs_ = delta_ / h;
  jointForces();
  double damping_power = 0.0;
  for (int k = 0; k < n; ++k) damping_power += damping_torque_.col(k).dot(links_.get(&LinkBlock::omega, k));
  input_power_ = joint_force_.col(0).dot(ends.base_velocity) + coupling_.dot(tip_vel_);
  next = x;
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector3d omega = links_.get(&LinkBlock::omega, k) + delta_.segment<3>(3 * k);
    const Eigen::Vector3d axis = links_.get(&LinkBlock::u, k);
    const double angle = h * omega.norm();
    Eigen::Vector3d turned = axis;
    if (angle > 0.0) turned = Eigen::AngleAxisd(angle, omega.normalized()) * axis;
    next.segment<3>(StateLayout::axis(k)) = turned;
    const double denominator = 1.0 + axis.z();
    next(StateLayout::twist(k)) +=
        h * (denominator > 1e-12 ? -omega.dot(kDown + axis) / denominator : -omega.dot(axis));
    next.segment<3>(StateLayout::omega(k)) = omega;
  }
  next(StateLayout::dissipated(n)) -= h * (drag_power_ + added_mass_power_ + damping_power);
  next(StateLayout::workInput(n)) += h * input_power_;
  return next.allFinite();
}

CABLE_HOT_PATH void ChainDynamics::kineticAndPotential(double& kinetic, double& potential) const {
  // Translation integrated along each link, rotation of the link's thickness, the load. Per-lane sums
  // (the padding lanes add zero: no mass, no weight), so that the loop runs on vectors.
  double kinetic_lanes[kBlockLanes] = {}, potential_lanes[kBlockLanes] = {};
  for (int b = 0; b < links_.blocks(); ++b) {
    const LinkBlock& block = links_.block(b);
    for (int i = 0; i < kBlockLanes; ++i) {
      const double l = block.length[i], m = block.mass_per_length[i];
      const Vec3 v = block.base_vel[i], c = block.axis_rate[i], omega = block.omega[i], axis = block.u[i];
      const double spin = dot(omega, axis);
      kinetic_lanes[i] += 0.5 * m * (l * dot(v, v) + l * l * dot(v, c) + (l * l * l / 3.0) * dot(c, c)) +
                          0.5 * block.thick_transverse[i] * (dot(omega, omega) - spin * spin) +
                          0.5 * block.polar[i] * spin * spin;
      potential_lanes[i] -= block.weight[i] * (block.base_pos.z[i] + 0.5 * l * axis.z);
    }
  }
  kinetic = 0.5 * props_.load_mass * tip_vel_.squaredNorm();
  potential = -load_weight_ * tip_pos_.z();
  for (int i = 0; i < kBlockLanes; ++i) {
    kinetic += kinetic_lanes[i];
    potential += potential_lanes[i];
  }
}

double ChainDynamics::mechanicalEnergy(const Eigen::VectorXd& x, const EndInputs& ends, double& magnitude) {
  kinematics(x, ends);
  return solvedMechanicalEnergy(x, magnitude);
}

double ChainDynamics::solvedMechanicalEnergy(const Eigen::VectorXd& x, double& magnitude) {
  double kinetic = 0.0, potential = 0.0;
  kineticAndPotential(kinetic, potential);
  const double elastic = elasticEnergy(x);
  magnitude = std::abs(kinetic) + std::abs(potential) + std::abs(elastic);
  return kinetic + potential + elastic;
}

void ChainDynamics::computeJointTorques(const Eigen::VectorXd& x) {
  if (stiffness_model_ == StiffnessModel::kPaper && !has_springs_) return;  // all zero since construction
  spring_torque_.setZero();
  damping_torque_.setZero();
  if (stiffness_model_ == StiffnessModel::kPaper) {
    if (has_springs_) paperSpringTorques(x);  // all zero (the presets): nothing to compute
  } else {
    bendingSpringTorques(x);
  }
  if (skip_damping_) damping_torque_.setZero();
  for (int k = 0; k < n_; ++k) links_.set(&LinkBlock::torque, k, spring_torque_.col(k) + damping_torque_.col(k));
}

void ChainDynamics::followAzimuths(const Eigen::VectorXd& x) {
  for (int k = 0; k < n_; ++k) {
    const Eigen::Vector3d axis = x.segment<3>(StateLayout::axis(k));
    // Straight down the azimuth is undefined: keep the previous one (as paperCoordinates() does).
    const double horizontal_squared = axis.x() * axis.x() + axis.y() * axis.y();
    if (horizontal_squared > kVerticalSine * kVerticalSine * axis.squaredNorm()) azimuths_.follow(k, axis.x(), axis.y());
  }
}

void ChainDynamics::paperCoordinates(const Eigen::VectorXd& x, Eigen::VectorXd& q, Eigen::VectorXd& qd) const {
  double psi_prev = 0.0, phi_prev = 0.0, psi_rate_prev = 0.0, phi_rate_prev = 0.0;
  for (int k = 0; k < n_; ++k) {
    const Eigen::Vector3d axis = x.segment<3>(StateLayout::axis(k)).normalized();
    const Eigen::Vector3d omega = x.segment<3>(StateLayout::omega(k));
    const double horizontal = std::hypot(axis.x(), axis.y());
    const double te = std::atan2(horizontal, axis.z());
    const double reference = azimuths_.reference(k);
    double psi = reference;
    if (horizontal > kVerticalSine) psi += wrapToPi(std::atan2(axis.x(), axis.y()) - reference);
    const double phi = x(StateLayout::twist(k)) - psi;
    Eigen::Vector3d nvec, evec;
    eulerAxes(te, psi, nvec, evec);
    const double te_rate = -omega.dot(nvec);
    // Straight down, the rotation about the vertical is all counted as torsion (only psi + phi is defined).
    const double psi_rate = horizontal > kVerticalSine ? omega.dot(evec) / std::sin(te) : 0.0;
    const double phi_rate = -omega.dot(axis) - psi_rate * std::cos(te);
    q.segment<3>(3 * k) << te, psi - psi_prev, phi - phi_prev;
    qd.segment<3>(3 * k) << te_rate, psi_rate - psi_rate_prev, phi_rate - phi_rate_prev;
    psi_prev = psi;
    phi_prev = phi;
    psi_rate_prev = psi_rate;
    phi_rate_prev = phi_rate;
  }
}

void ChainDynamics::stateFromPaper(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, Eigen::VectorXd& x) const {
  x.setZero(stateSize());
  double psi = 0.0, phi = 0.0, psi_rate = 0.0, phi_rate = 0.0;
  for (int k = 0; k < n_; ++k) {
    psi += q(3 * k + 1);
    phi += q(3 * k + 2);
    psi_rate += qd(3 * k + 1);
    phi_rate += qd(3 * k + 2);
    const double te = q(3 * k), te_rate = qd(3 * k);
    const Eigen::Vector3d axis = linkAxis(te, psi);
    Eigen::Vector3d nvec, evec;
    eulerAxes(te, psi, nvec, evec);
    x.segment<3>(StateLayout::axis(k)) = axis;
    x(StateLayout::twist(k)) = psi + phi;
    x.segment<3>(StateLayout::omega(k)) = -psi_rate * kDown - te_rate * nvec - phi_rate * axis;
  }
}

void ChainDynamics::paperSpringTorques(const Eigen::VectorXd& x) {
  // The paper's springs and dampers act on the generalized coordinates: Q = -K q - C q'. Mapped to
  // world torques by virtual power: tau = -Q_te n + (Q_psi - Q_phi cos te)/sin te e - Q_phi u, with
  // Q in the absolute angles (Q_psi_i = Q_a_i - Q_a_{i+1}). Azimuth and torsion springs have no limit
  // as sin te -> 0 unless Q_psi = Q_phi: the paper's K is singular there (docs/MODEL.md section 5).
  const int n = n_;
  const LinkProperties& p = props_;
  Eigen::Matrix<double, 3, 1> q_next = Eigen::Vector3d::Zero(), c_next = Eigen::Vector3d::Zero();
  // Paper coordinates in a forward pass, then torques backwards so Q_a_{i+1}, Q_t_{i+1} are at hand.
  paperCoordinates(x, paper_q_, paper_qd_);
  double psi_sum = 0.0;
  for (int k = 0; k < n; ++k) paper_psi_(k) = (psi_sum += paper_q_(3 * k + 1));
  for (int k = n - 1; k >= 0; --k) {
    const Eigen::Vector3d stiffness(p.stiffness_elevation(k), p.stiffness_azimuth(k), p.stiffness_torsion(k));
    const Eigen::Vector3d damping(p.damping_elevation(k), p.damping_azimuth(k), p.damping_torsion(k));
    const Eigen::Vector3d q_spring = -stiffness.cwiseProduct(paper_q_.segment<3>(3 * k));
    const Eigen::Vector3d q_damper = -damping.cwiseProduct(paper_qd_.segment<3>(3 * k));
    const double te = paper_q_(3 * k);
    const Eigen::Vector3d axis = links_.get(&LinkBlock::u, k);
    Eigen::Vector3d nvec, evec;
    eulerAxes(te, paper_psi_(k), nvec, evec);
    const double sine = std::sin(te), cosine = std::cos(te);
    const auto to_torque = [&](const Eigen::Vector3d& own, const Eigen::Vector3d& next) -> Eigen::Vector3d {
      const double q_te = own(0), q_psi = own(1) - next(1), q_phi = own(2) - next(2);
      const double across = std::abs(sine) > kVerticalSine ? (q_psi - q_phi * cosine) / sine : 0.0;
      return -q_te * nvec + across * evec - q_phi * axis;
    };
    spring_torque_.col(k) = to_torque(q_spring, q_next);
    damping_torque_.col(k) = to_torque(q_damper, c_next);
    q_next = q_spring;
    c_next = q_damper;
  }
}

void ChainDynamics::bendingSpringTorques(const Eigen::VectorXd& x) {
  // Joint k couples link k-1 (the fixed base direction, straight down, for k = 0) and link k.
  const LinkProperties& p = props_;
  for (int k = 0; k < n_; ++k) {
    const Eigen::Vector3d prev = k > 0 ? links_.get(&LinkBlock::u, k - 1) : kDown;
    const Eigen::Vector3d axis = links_.get(&LinkBlock::u, k);
    const JointGeometry g =
        jointGeometry(prev, axis, x(StateLayout::twist(k)), k > 0 ? x(StateLayout::twist(k - 1)) : 0.0);
    // Bend: V = 1/2 k_b beta^2; dV = k_b beta/sin(beta) (prev x u_k) . dTheta_k.
    const Eigen::Vector3d bend_torque = -p.stiffness_elevation(k) * angleOverSine(g.bend, g.sine) * g.cross;
    // Twist: a rotation dTheta of link k changes it by -(prev + u_k)/(1 + prev.u_k) . dTheta.
    const Eigen::Vector3d mean_axis = (prev + axis) / (1.0 + g.cosine);
    const Eigen::Vector3d twist_torque = p.stiffness_torsion(k) * g.twist * mean_axis;
    // Dampers on the relative angular velocity: across the mean axis (bending) and about it (twist).
    const Eigen::Vector3d relative =
        links_.get(&LinkBlock::omega, k) - (k > 0 ? links_.get(&LinkBlock::omega, k - 1) : Eigen::Vector3d::Zero());
    const Eigen::Vector3d direction = (prev + axis).normalized();
    const double about = relative.dot(direction);
    const Eigen::Vector3d damper =
        -p.damping_elevation(k) * (relative - about * direction) - p.damping_torsion(k) * about * direction;
    spring_torque_.col(k) += bend_torque + twist_torque;
    damping_torque_.col(k) += damper;
    if (k > 0) {
      spring_torque_.col(k - 1) -= bend_torque + twist_torque;
      damping_torque_.col(k - 1) -= damper;
    }
  }
}

double ChainDynamics::elasticEnergy(const Eigen::VectorXd& x) {
  double energy = 0.0;
  const LinkProperties& p = props_;
  if (stiffness_model_ == StiffnessModel::kPaper) {
    if (!has_springs_) return 0.0;
    Eigen::VectorXd& q = paper_q_;
    paperCoordinates(x, q, paper_qd_);
    for (int k = 0; k < n_; ++k) {
      energy += 0.5 * (p.stiffness_elevation(k) * q(3 * k) * q(3 * k) + p.stiffness_azimuth(k) * q(3 * k + 1) * q(3 * k + 1) +
                       p.stiffness_torsion(k) * q(3 * k + 2) * q(3 * k + 2));
    }
    return energy;
  }
  for (int k = 0; k < n_; ++k) {
    const Eigen::Vector3d prev = k > 0 ? Eigen::Vector3d(x.segment<3>(StateLayout::axis(k - 1)).normalized()) : kDown;
    const Eigen::Vector3d axis = x.segment<3>(StateLayout::axis(k)).normalized();
    const JointGeometry g =
        jointGeometry(prev, axis, x(StateLayout::twist(k)), k > 0 ? x(StateLayout::twist(k - 1)) : 0.0);
    energy += 0.5 * p.stiffness_elevation(k) * g.bend * g.bend + 0.5 * p.stiffness_torsion(k) * g.twist * g.twist;
  }
  return energy;
}

}  // namespace cable_dynamics
