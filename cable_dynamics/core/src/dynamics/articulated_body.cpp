/// \file
/// \brief The articulated-body recursion (articulated_body.h).
///
/// A spherical joint passes a force and no torque, so what the outboard part of the chain shows its
/// parent is a 3x3 effective mass M_k and a bias force f_k at joint k: the force on the outboard part is
/// J_k = M_k a_k + f_k for a base-end acceleration a_k. A link's spin (its angular acceleration along its
/// axis) couples to nothing, and only the two transverse components move the link, so the joint's
/// 3x3 block reduces to a 2x2 one in a basis (e1, e2) of the plane normal to the link. Every operation
/// is on 3-vectors, symmetric 3x3 matrices and 2x2 matrices, with no heap allocation.
///
/// The base-end accelerations split as a_k = a0_k + d_k: a0_k, the known part (kinematics: the sum
/// of l_j beta_j inboard of k, the base's own acceleration included) and d_k from the angular
/// accelerations, with d_0 = 0 and d_{k+1} = d_k + l_k C_k y_k. The recursion carries the force on the
/// outboard part as J_k = M_k d_k + F_k (F_k = M_k a0_k + f_k): the known accelerations then enter
/// each link's own bias terms only, which the first pass forms on vectors, and not the serial pass.
///
/// This is the hot path of every evaluation, with the kinematics and the drag: keep it free of heap
/// allocation and of per-link branches, and measure any change with bench/ (fluid_step).
#include "cable_dynamics/dynamics/articulated_body.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "cable_dynamics/dynamics/fluid.h"
#include "cable_dynamics/dynamics/hot_path.h"
#include "cable_dynamics/dynamics/kinematics.h"

namespace cable_dynamics {
namespace {

/// Unit vectors e1, e2 with (e1, e2, u) right-handed, for a unit u, without a branch on the
/// direction of u (Duff et al., "Building an orthonormal basis, revisited", JCGT 2017).
inline void normalPlaneBasis(const Vec3& u, Vec3& e1, Vec3& e2) {
  const double sign = std::copysign(1.0, u.z);
  const double a = -1.0 / (sign + u.z);
  const double b = u.x * u.y * a;
  e1 = {1.0 + sign * u.x * u.x * a, sign * b, -sign * u.x};
  e2 = {b, sign + u.y * u.y * a, -u.y};
}

/// What each link contributes on its own: its plane basis, inertia and bias (velocity terms: the
/// centripetal beta = u'' at zero angular acceleration and the gyroscopic torque; the known
/// acceleration; minus the external forces). Every link alike: the loop runs over a block's lanes.
EIGEN_ALWAYS_INLINE void linkTermsPass(const ChainDeployment& deployed, LinkBlocks& links) {
  for (int b = deployed.firstBlock(); b < links.blocks(); ++b) {
    const LinkConstants& c = deployed.block(b);
    LinkBlock& block = links.block(b);
    CABLE_LANE_LOOP
    for (int i = 0; i < kBlockLanes; ++i) {
      const Vec3 u = block.u[i], beta = block.beta[i], omega = block.omega[i], torque = block.torque[i];
      const Vec3 axis_rate = block.axis_rate[i], known = block.known_acc[i];
      const double l = c.length[i], added = c.added[i];
      Vec3 e1, e2;
      normalPlaneBasis(u, e1, e2);
      block.e1.set(i, e1);
      block.e2.set(i, e2);
      // l A = l m' I + l m_a' (I - u u^T), and the attachments' (m_p + m_pa) I.
      const double lm = c.translational[i], la = l * added;
      block.own_mass.set(i, {lm - la * u.x * u.x, -la * u.x * u.y, -la * u.x * u.z, lm - la * u.y * u.y,
                             -la * u.y * u.z, lm - la * u.z * u.z});
      // The link's points at s accelerate by a0 + s beta at y = 0: the force integral A (l a0 + l^2/2 beta),
      // its first moment A (l^2/2 a0 + l^3/3 beta), of which only u x (...) counts, where A acts as m' + m_a';
      // the attachments add their isotropic mass moments to each.
      const Vec3 mean = l * known + (0.5 * l * l) * beta;
      block.own_force.set(i, lm * known + c.half_moment[i] * beta - (added * dot(u, mean)) * u - block.force[i]);
      block.own_moment.set(i, c.half_moment[i] * known + c.third_moment[i] * beta - block.moment[i]);
      // omega x (I_rot omega) - tau, with I_rot = I_thick (I - u u^T) + I_P u u^T.
      const double gyroscopic = c.polar[i] - c.thick_transverse[i];
      const Vec3 bias_torque = (gyroscopic * dot(u, omega)) * axis_rate - torque;
      block.bias_torque1[i] = dot(e1, bias_torque);
      block.bias_torque2[i] = dot(e2, bias_torque);
      // Spin: I_P (omega'.u) = tau.u, since a spherical joint passes no torque along the link.
      block.spin_acc[i] = c.inverse_polar[i] * dot(u, torque);
    }
  }
}

/// With axial elasticity: each link's far-end point (LinkConstants::far_mass, beyond its stretch) moves with
/// the far end, whose known acceleration is a0 + (l + s) beta + 2 s' u' (kinematics.h); its bias
/// m_f a0_far - w_f e_z - f_d u joins the outboard part's in the backward pass, f_d u being the far half's
/// skin friction (LinkBlock::far_drag). On vectors, ahead of the serial pass.
EIGEN_ALWAYS_INLINE void farPointPass(const ChainDeployment& deployed, LinkBlocks& links) {
  for (int b = deployed.firstBlock(); b < links.blocks(); ++b) {
    const LinkConstants& c = deployed.block(b);
    LinkBlock& block = links.block(b);
    CABLE_LANE_LOOP
    for (int i = 0; i < kBlockLanes; ++i) {
      const Vec3 far_acc = farEndKnownAcceleration(block.known_acc[i], block.beta[i], block.axis_rate[i],
                                                   c.length[i] + block.stretch[i], block.stretch_rate[i]);
      block.far_bias.set(i, c.far_mass[i] * far_acc - Vec3{0.0, 0.0, c.far_weight[i]} - block.far_drag[i] * block.u[i]);
    }
  }
}

/// From the load inwards, fold everything outboard of joint k into (M_k, F_k). The load is a point mass
/// at the tip: J_n = m_L a_n - F_L = m_L d_n + (m_L a0_n - F_L). Returns F_0, the force on the whole
/// chain at the base when the base end does not accelerate beyond its known part (d_0 = 0).
///
/// With axial elasticity (kAxial) each link's far end is a prismatic joint along u: what is outboard of
/// it, (M, F) at the far end, passes along u only the stretch's tension T (u . J = -T), so eliminating
/// s'' = -(T + u . F + (M u) . d_q) / (u^T M u) leaves M - (M u)(M u)^T / (u^T M u) and
/// F - (M u)(T + u . F) / (u^T M u) at the rigid far end, l + s from the base end (the lever below).
/// An exact anchor's sums over the chain (docs/MODEL.md section 14), formed in a backward pass: the tip's
/// d_n at the present tip force, and its change per unit change of the tip's bias force F_n (3x3, symmetric,
/// negative semi-definite: minus the tip's inverse articulated inertia with the base held).
///
/// d_n = sum_k Psi_{k+1} c_k with Psi_{k+1} = T_{n-1} ... T_{k+1} (forwardPass: d_{k+1} = T_k d_k + c_k),
/// and F_{k+1} = Psi_{k+1}^T F_n + (the rest), since the backward pass moves a force inwards by T_k^T. So
/// dd_n/dF_n = sum_k Psi_{k+1} N_k Psi_{k+1}^T with N_k = dc_k/dF_{k+1} = P (dc_rot/dF') P^T - u u^T / (u^T M u),
/// dc_rot/dF' = -(s_a p p^T + s_b (p r^T + r p^T) + s_d r r^T) / det(S) (p = l e1, r = l e2), P = I - u g^T.
struct HoldSums {
  Eigen::Matrix3d psi = Eigen::Matrix3d::Identity();  ///< Psi_{k+1}, from the tip inwards [-]
  Eigen::Vector3d tip_delta = Eigen::Vector3d::Zero();  ///< d_n [m/s^2]
  Eigen::Matrix3d response = Eigen::Matrix3d::Zero();  ///< dd_n/dF_n [1/kg]
};

template <bool kAxial, bool kHeld>
EIGEN_ALWAYS_INLINE Vec3 backwardPass(const ChainModel& model, ChainData& data, bool all_joint_forces,
                                      HoldSums* sums = nullptr) {
  const double load_inertia = model.load().inertia;
  Symmetric3 child = Symmetric3::scaledIdentity(load_inertia);
  Vec3 child_force = toVec3(load_inertia * data.tip_known_acc - data.load_external);
  if (model.body().active) {  // an ROV body on a ball joint: its 3x3 mass at the tip and its bias (rov_body.h)
    const Eigen::Matrix3d& m = data.body.tip_mass;
    child = {child.xx + m(0, 0), m(0, 1), m(0, 2), child.yy + m(1, 1), m(1, 2), child.zz + m(2, 2)};
    child_force = child_force + toVec3(m * data.tip_known_acc + data.body.tip_bias);
  }
  for (int k = model.links() - 1; k >= data.deployed.firstLink(); --k) {
    const LinkConstants& c = data.deployed.of(k);
    LinkBlock& block = data.links.of(k);
    const int i = LinkBlocks::lane(k);
    // The lever from the base end to the far end, l (+ s with axial elasticity).
    const double l = kAxial ? c.length[i] + block.stretch[i] : c.length[i];
    double stretch_inverse = 0.0;  // 1 / (u^T M u) of the stretch's elimination (0 when rigid or locked)
    if (kAxial) {
      // The far-end point, outboard of the stretch and inboard of joint k + 1: it moves as that joint does.
      const double far_mass = c.far_mass[i];
      child = {child.xx + far_mass, child.xy, child.xz, child.yy + far_mass, child.yz, child.zz + far_mass};
      child_force = child_force + block.far_bias[i];
      const bool locked = model.stretchLocked(k);
      const Vec3 u = block.u[i], m_u = child * u;
      const double inverse = locked ? 0.0 : 1.0 / dot(u, m_u);
      stretch_inverse = inverse;
      const double bias = inverse * (block.axial_tension[i] + dot(u, child_force));
      block.stretch_gain.set(i, inverse * m_u);
      block.stretch_bias[i] = bias;
      child = {child.xx - inverse * m_u.x * m_u.x, child.xy - inverse * m_u.x * m_u.y, child.xz - inverse * m_u.x * m_u.z,
               child.yy - inverse * m_u.y * m_u.y, child.yz - inverse * m_u.y * m_u.z, child.zz - inverse * m_u.z * m_u.z};
      child_force = child_force - bias * m_u;
    }
    const Vec3 e1 = block.e1[i], e2 = block.e2[i];
    // Transverse inertia about joint k in the plane: S = c1 I + l^2 C^T M C with C = [u]x^T [e1 e2]
    // = [-e2, e1]; c1 is the link's own (translation integral plus thickness).
    const Vec3 m_e1 = child * e1, m_e2 = child * e2;
    const double l2 = l * l, c1 = c.own_transverse[i];
    const double s_a = c1 + l2 * dot(e2, m_e2), s_b = -l2 * dot(e1, m_e2), s_d = c1 + l2 * dot(e1, m_e1);
    // Coupling of the base-end acceleration to the transverse ones: W = E C with E = l^2/2 m' I + l M
    // (A [u]x = (m' + m_a') [u]x for A = m' I + m_a' (I - u u^T)).
    const double half = c.half_moment[i];
    const Vec3 w1 = -(l * m_e2 + half * e2);
    const Vec3 w2 = l * m_e1 + half * e1;
    // X = W S^-1 = V / det with V = W adj(S), and M_k = l A + M_{k+1} - X W^T = l A + M_{k+1} - Z / det
    // with Z = V W^T: everything but one multiplication can go on while the division runs, which
    // shortens the serial chain from M_{k+1} to M_k.
    const double inv_det = 1.0 / (s_a * s_d - s_b * s_b);
    const Vec3 v1 = s_d * w1 - s_b * w2, v2 = s_a * w2 - s_b * w1;
    const Symmetric3 own = block.own_mass[i];
    const Symmetric3 sum = {own.xx + child.xx, own.xy + child.xy, own.xz + child.xz,
                            own.yy + child.yy, own.yz + child.yz, own.zz + child.zz};
    const Symmetric3 z = {v1.x * w1.x + v2.x * w2.x, v1.x * w1.y + v2.x * w2.y, v1.x * w1.z + v2.x * w2.z,
                          v1.y * w1.y + v2.y * w2.y, v1.y * w1.z + v2.y * w2.z, v1.z * w1.z + v2.z * w2.z};
    const Symmetric3 m = {sum.xx - inv_det * z.xx, sum.xy - inv_det * z.xy, sum.xz - inv_det * z.xz,
                          sum.yy - inv_det * z.yy, sum.yz - inv_det * z.yz, sum.zz - inv_det * z.zz};
    const Vec3 x1 = inv_det * v1, x2 = inv_det * v2;
    // Bias force: the link's own plus F_{k+1}; torque about joint k u x moment + bias torque, with
    // `moment` the link's own first moment plus l F_{k+1} (MODEL.md section 4 calls them h and q).
    const Vec3 moment = block.own_moment[i] + l * child_force;
    const double g1 = block.bias_torque1[i] - dot(e2, moment), g2 = block.bias_torque2[i] + dot(e1, moment);
    const Vec3 force = block.own_force[i] + child_force - (g1 * x1 + g2 * x2);
    if (all_joint_forces) {  // for J_k = M_k d_k + F_k after the forward pass (J_0 = F_0 needs neither)
      block.mass.set(i, m);
      block.bias.set(i, force);
    }
    block.x1.set(i, x1);
    block.x2.set(i, x2);
    block.y1[i] = -inv_det * (s_d * g1 - s_b * g2);  // y_g = -S^-1 g
    block.y2[i] = -inv_det * (s_a * g2 - s_b * g1);
    if (kHeld) {
      // HoldSums: with a = Psi P p, b = Psi P r, w = Psi u, Psi c_k = y2 a - y1 b - bias w and
      // Psi N_k Psi^T = -(s_a a a^T + s_b (a b^T + b a^T) + s_d b b^T) / det - w w^T / (u^T M u).
      const Eigen::Vector3d p = toEigen(l * e1), r = toEigen(l * e2), u = toEigen(block.u[i]);
      Eigen::Vector3d pp = p, pr = r, gain = Eigen::Vector3d::Zero();
      double bias = 0.0, inverse = 0.0;
      if (kAxial) {
        gain = toEigen(block.stretch_gain[i]);  // g = M u / (u^T M u): P v = v - u (g . v)
        bias = block.stretch_bias[i];
        inverse = stretch_inverse;
        pp -= gain.dot(p) * u;
        pr -= gain.dot(r) * u;
      }
      const Eigen::Vector3d a = sums->psi * pp, b = sums->psi * pr, w = sums->psi * u;
      sums->tip_delta += block.y2[i] * a - block.y1[i] * b - bias * w;
      sums->response -= inv_det * (s_a * a * a.transpose() + s_b * (a * b.transpose() + b * a.transpose()) +
                                   s_d * b * b.transpose()) +
                        inverse * w * w.transpose();
      // Psi_k = Psi_{k+1} P T_rot = Psi - w g^T + b x1^T - a x2^T.
      sums->psi += b * toEigen(x1).transpose() - a * toEigen(x2).transpose() - w * gain.transpose();
    }
    child = m;
    child_force = force;
  }
  return child_force;
}

/// The one serial recursion forward: y = y_g - X^T d_k (the transverse angular accelerations in the
/// (e1, e2) basis) and C y = y2 e1 - y1 e2 make d_{k+1} = T_k d_k + c_k, with T_k = I + l (e2 x1^T -
/// e1 x2^T) and c_k = l (y_g2 e1 - y_g1 e2), formed on vectors for a block's links just before its turn.
/// The serial pass is then three short dot products per link. Returns d_n, the tip's.
///
/// With axial elasticity the far end's stretch adds s'' u = -(b + g . d_q) u to the far end's d_q =
/// T_k d_k + c_k (g, b: the backward pass's stretch_gain and stretch_bias): P = I - u g^T folds into
/// T_k and c_k, so the serial pass is unchanged.
template <bool kAxial>
EIGEN_ALWAYS_INLINE Vec3 forwardPass(const ChainModel& model, const ChainDeployment& deployed, LinkBlocks& links) {
  const int n = model.links(), first = deployed.firstLink();
  Vec3 d = {0.0, 0.0, 0.0};  // the base translates as prescribed: d_0 = 0
  // The drum's slots (a winch) take no part: their d stays 0 (their rates are not used).
  for (int k = 0; k < first; ++k) links.of(k).delta_acc.set(LinkBlocks::lane(k), d);
  for (int b = first / kBlockLanes; b < links.blocks(); ++b) {
    const LinkConstants& c = deployed.block(b);
    LinkBlock& block = links.block(b);
    Lanes3 row_x, row_y, row_z, offset;  // T_k's rows and c_k
    for (int i = 0; i < kBlockLanes; ++i) {
      const double l = kAxial ? c.length[i] + block.stretch[i] : c.length[i];
      const Vec3 p = l * block.e1[i], r = l * block.e2[i], x1 = block.x1[i], x2 = block.x2[i];
      Vec3 tx = {1.0 + r.x * x1.x - p.x * x2.x, r.x * x1.y - p.x * x2.y, r.x * x1.z - p.x * x2.z};
      Vec3 ty = {r.y * x1.x - p.y * x2.x, 1.0 + r.y * x1.y - p.y * x2.y, r.y * x1.z - p.y * x2.z};
      Vec3 tz = {r.z * x1.x - p.z * x2.x, r.z * x1.y - p.z * x2.y, 1.0 + r.z * x1.z - p.z * x2.z};
      Vec3 off = block.y2[i] * p - block.y1[i] * r;
      if (kAxial) {  // rows of P T = T - u (g^T T), and P c - b u
        const Vec3 u = block.u[i], g = block.stretch_gain[i];
        const Vec3 gt = g.x * tx + g.y * ty + g.z * tz;
        tx = tx - u.x * gt;
        ty = ty - u.y * gt;
        tz = tz - u.z * gt;
        off = off - (dot(g, off) + block.stretch_bias[i]) * u;
      }
      row_x.set(i, tx);
      row_y.set(i, ty);
      row_z.set(i, tz);
      offset.set(i, off);
    }
    const int count = std::min(kBlockLanes, n - b * kBlockLanes);
    for (int i = std::max(0, first - b * kBlockLanes); i < count; ++i) {
      block.delta_acc.set(i, d);
      // c_k first: each component is then three fused multiply-adds in a row on the serial chain, not a
      // product, two of them and an addition.
      const Vec3 off = offset[i], rx = row_x[i], ry = row_y[i], rz = row_z[i];
      d = {off.x + rx.x * d.x + rx.y * d.y + rx.z * d.z, off.y + ry.x * d.x + ry.y * d.y + ry.z * d.z,
           off.z + rz.x * d.x + rz.y * d.y + rz.z * d.z};
    }
  }
  return d;
}

/// On vectors again, what follows from d_k: angular accelerations and the added-mass power [W].
EIGEN_ALWAYS_INLINE double accelerationPass(const ChainDeployment& deployed, LinkBlocks& links) {
  double power[kBlockLanes] = {};
  for (int b = deployed.firstBlock(); b < links.blocks(); ++b) {
    const LinkConstants& c = deployed.block(b);
    LinkBlock& block = links.block(b);
    CABLE_LANE_LOOP
    for (int i = 0; i < kBlockLanes; ++i) {
      const Vec3 delta = block.delta_acc[i], e1 = block.e1[i], e2 = block.e2[i], u = block.u[i];
      const double y1 = block.y1[i] - dot(block.x1[i], delta), y2 = block.y2[i] - dot(block.x2[i], delta);
      block.omega_rate.set(i, y1 * e1 + y2 * e2 + block.spin_acc[i] * u);
      // u'' = omega' x u + beta, with omega' x u = C y = y2 e1 - y1 e2.
      const Vec3 axis_acc = y2 * e1 - y1 * e2 + block.beta[i];
      Vec3 added_base, added_axis;
      linkAddedMassPowerWeights(c, i, u, block.axis_rate[i], block.base_vel[i], added_base, added_axis);
      power[i] += dot(added_base, block.known_acc[i] + delta) + dot(added_axis, axis_acc);
    }
  }
  double total = 0.0;
  for (int i = 0; i < kBlockLanes; ++i) total += power[i];
  return total;
}

/// J_k = M_k d_k + F_k; at the base link (firstLink()) d = 0: J = F. The load's force from the tip's acceleration.
EIGEN_ALWAYS_INLINE void jointForcesPass(const ChainModel& model, ChainData& data, const Vec3& base_force,
                                         const Vec3& tip_delta, bool all_joint_forces) {
  const int first = data.deployed.firstLink();
  data.joint_force.leftCols(first).setZero();  // the drum's slots (a winch)
  data.joint_force.col(first) = toEigen(base_force);
  for (int k = first + 1; all_joint_forces && k < model.links(); ++k) {
    const LinkBlock& block = data.links.of(k);
    const int i = LinkBlocks::lane(k);
    data.joint_force.col(k) = toEigen(block.mass[i] * block.delta_acc[i] + block.bias[i]);
  }
  const Eigen::Vector3d tip_acc = data.tip_known_acc + toEigen(tip_delta);
  data.load_force = model.load().inertia * tip_acc - data.load_external;
  if (model.body().active) data.load_force += finishRovBody(model.body(), tip_acc, data.body);
  // The load's added-mass force -m_a a_tip: its power goes with the links' (the kinetic energy is the
  // structure's alone).
  data.added_mass_power -= (model.load().inertia - model.load().mass) * tip_acc.dot(data.tip_velocity);
}

/// With axial elasticity: s''_k = u_k . (d_{k+1} - d_k), the part of the far end's acceleration along the
/// link that its rotation does not give (d_n: the tip's).
void stretchAccelerationPass(const ChainModel& model, const ChainDeployment& deployed, LinkBlocks& links, const Vec3& tip_delta) {
  const int n = model.links();
  for (int k = deployed.firstLink(); k < n; ++k) {
    LinkBlock& block = links.of(k);
    const int i = LinkBlocks::lane(k);
    const Vec3 next = k + 1 < n ? links.of(k + 1).delta_acc[LinkBlocks::lane(k + 1)] : tip_delta;
    block.stretch_acc[i] = dot(block.u[i], next - block.delta_acc[i]);
  }
  if (model.lastStretchLocked()) links.of(n - 1).stretch_acc[LinkBlocks::lane(n - 1)] = 0.0;
}

/// An exact anchor's force on the load: the one that gives the tip data.tip_demand, from a backward pass at
/// the present loads (HoldSums). A force f on the load changes F_n by -f, so the tip's acceleration is
/// a_free - R f with R = dd_n/dF_n; R is inverted on its range (a direction the chain cannot move the tip
/// in, such as along a straight chain of rigid links, gets no force). Into data.coupling and load_external.
/// Returns false when the sums are not finite.
HoldSums holdSums(const ChainModel& model, ChainData& data) {
  HoldSums sums;
  if (model.axial()) {
    backwardPass<true, true>(model, data, false, &sums);
  } else {
    backwardPass<false, true>(model, data, false, &sums);
  }
  return sums;
}

/// The force f on the load that changes the tip's acceleration by `change` [m/s^2]: -R f = change, R being
/// sums.response, solved on R's range (its eigenvalues below 1e-12 of the largest: no force).
Eigen::Vector3d tipForceFor(const HoldSums& sums, const Eigen::Vector3d& change) {
  const Eigen::Matrix3d compliance = -0.5 * (sums.response + sums.response.transpose());  // [1/kg]
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(compliance);
  const Eigen::Vector3d values = eigen.eigenvalues();
  const double floor = 1e-12 * values.cwiseAbs().maxCoeff();
  Eigen::Vector3d along = eigen.eigenvectors().transpose() * change;
  for (int j = 0; j < 3; ++j) along(j) = values(j) > floor ? along(j) / values(j) : 0.0;
  return eigen.eigenvectors() * along;
}

bool solveHoldForce(const ChainModel& model, ChainData& data) {
  const HoldSums sums = holdSums(model, data);
  const Eigen::Vector3d shortfall = data.tip_demand - (data.tip_known_acc + sums.tip_delta);
  if (!sums.response.allFinite() || !shortfall.allFinite()) return false;
  data.coupling = tipForceFor(sums, shortfall);
  data.load_external += data.coupling;
  return data.coupling.allFinite();
}

/// The backward and forward passes after linkTermsPass (solveArticulatedBody's, without the hold). Inlined
/// into solveArticulatedBody's clones (hot_path.h): called out of line, RK4's recursion ran as the baseline
/// build's code in every clone (bench/physical_limit.sh: no FMA in 60 % of an RK4 step).
EIGEN_ALWAYS_INLINE void solvePasses(const ChainModel& model, ChainData& data, bool all_joint_forces) {
  const bool axial = model.axial();
  const Vec3 base_force = axial ? backwardPass<true, false>(model, data, all_joint_forces)
                                : backwardPass<false, false>(model, data, all_joint_forces);
  const Vec3 tip_delta = axial ? forwardPass<true>(model, data.deployed, data.links) : forwardPass<false>(model, data.deployed, data.links);
  if (axial) stretchAccelerationPass(model, data.deployed, data.links, tip_delta);
  data.added_mass_power = accelerationPass(data.deployed, data.links);
  jointForcesPass(model, data, base_force, tip_delta, all_joint_forces);
}

}  // namespace

bool tipVelocityProjection(const ChainModel& model, ChainData& data, const Eigen::Vector3d& velocity_change,
                           Eigen::Matrix3Xd& omega_change, Eigen::VectorXd& stretch_rate_change) {
  const int n = model.links(), first = data.deployed.firstLink();
  omega_change.setZero(3, n);
  stretch_rate_change.setZero(model.axial() ? n : 0);
  linkTermsPass(data.deployed, data.links);
  if (model.axial()) farPointPass(data.deployed, data.links);
  // The impulse p on the load that changes the tip's velocity by `velocity_change`: -R p = dv (an impulse
  // is a force over unit time).
  const Eigen::Vector3d impulse = tipForceFor(holdSums(model, data), velocity_change);
  if (!impulse.allFinite()) return false;
  // The links' response to it: the accelerations with the load pushed by p less those without (linear in
  // p, every other term cancels), as velocity changes (an impulse over unit time).
  solvePasses(model, data, false);
  for (int k = first; k < n; ++k) {
    omega_change.col(k) = -data.links.get(&LinkBlock::omega_rate, k);
    if (model.axial()) stretch_rate_change(k) = -data.links.of(k).stretch_acc[LinkBlocks::lane(k)];
  }
  data.load_external += impulse;
  solvePasses(model, data, false);
  data.load_external -= impulse;
  for (int k = first; k < n; ++k) {
    omega_change.col(k) += data.links.get(&LinkBlock::omega_rate, k);
    if (model.axial()) stretch_rate_change(k) += data.links.of(k).stretch_acc[LinkBlocks::lane(k)];
  }
  return omega_change.allFinite() && stretch_rate_change.allFinite();
}

CABLE_HOT_PATH bool solveArticulatedBody(const ChainModel& model, ChainData& data, bool all_joint_forces) {
  linkTermsPass(data.deployed, data.links);
  if (model.axial()) farPointPass(data.deployed, data.links);
  if (model.heldTip() && !solveHoldForce(model, data)) return false;
  solvePasses(model, data, all_joint_forces);
  return true;
}

}  // namespace cable_dynamics
