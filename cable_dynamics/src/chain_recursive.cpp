/// \file
/// \brief The O(n) formulation: an articulated-body recursion (Featherstone) written out for a chain of
/// axisymmetric links on spherical joints (docs/MODEL.md section 4).
///
/// A spherical joint passes a force and no torque, so what the outboard part of the chain shows its
/// parent is a 3x3 effective mass M_k and a bias force f_k at joint k: the force on the outboard part is
/// J_k = M_k a_k + f_k for a base-end acceleration a_k. A link's spin (its angular acceleration along its
/// axis) couples to nothing, and only the two transverse components move the link, so the joint's
/// 3x3 block reduces to a 2x2 one in a basis (e1, e2) of the plane normal to the link. Every operation
/// is on 3-vectors, symmetric 3x3 matrices and 2x2 matrices, with no heap allocation.
#include <cmath>

#include <Eigen/Geometry>

#include "cable_dynamics/chain_dynamics.h"
#include "cable_dynamics/hot_path.h"

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

}  // namespace

CABLE_HOT_PATH void ChainDynamics::solveRecursive(bool all_joint_forces) {
  const int n = n_;
  // What each link contributes on its own: its plane basis, inertia and bias (velocity terms: the
  // centripetal beta = u'' at zero angular acceleration and the gyroscopic torque, minus the external
  // forces). Every link alike: the loop runs over a block's lanes, on vectors.
  for (int b = 0; b < links_.blocks(); ++b) {
    LinkBlock& block = links_.block(b);
    for (int i = 0; i < kBlockLanes; ++i) {
      const Vec3 u = block.u[i], beta = block.beta[i], omega = block.omega[i], torque = block.torque[i];
      const Vec3 axis_rate = block.axis_rate[i];
      const double l = block.length[i], across = block.across[i], added = block.added[i];
      Vec3 e1, e2;
      normalPlaneBasis(u, e1, e2);
      block.e1.set(i, e1);
      block.e2.set(i, e2);
      // l A = l m' I + l m_a' (I - u u^T).
      const double lm = l * across, la = l * added;
      block.own_mass.set(i, {lm - la * u.x * u.x, -la * u.x * u.y, -la * u.x * u.z, lm - la * u.y * u.y,
                             -la * u.y * u.z, lm - la * u.z * u.z});
      const Vec3 a_beta = across * beta - (added * dot(u, beta)) * u;
      block.own_force.set(i, (0.5 * l * l) * a_beta - block.force[i]);
      block.own_moment.set(i, block.third_moment[i] * beta - block.moment[i]);
      // omega x (I_rot omega) - tau, with I_rot = I_thick (I - u u^T) + I_P u u^T.
      const double gyroscopic = block.polar[i] - block.thick_transverse[i];
      const Vec3 q = (gyroscopic * dot(u, omega)) * axis_rate - torque;
      block.q1[i] = dot(e1, q);
      block.q2[i] = dot(e2, q);
      // Spin: I_P (omega'.u) = tau.u, since a spherical joint passes no torque along the link.
      block.spin_acc[i] = block.inverse_polar[i] * dot(u, torque);
      Vec3 added_base, added_axis;
      addedMassPowerWeights(added, l, u, axis_rate, block.base_vel[i], added_base, added_axis);
      block.added_base.set(i, added_base);
      block.added_axis.set(i, added_axis);
    }
  }
  // Backward: from the load inwards, fold everything outboard of joint k into (M_k, f_k).
  // The load is a point mass at the tip: J_n = m_L a_n - F_L.
  Symmetric3 child = Symmetric3::scaledIdentity(load_inertia_);
  Vec3 child_force = -toVec3(load_external_);
  for (int k = n - 1; k >= 0; --k) {
    LinkBlock& block = links_.of(k);
    const int i = LinkBlocks::lane(k);
    const double l = block.length[i];
    const Vec3 e1 = block.e1[i], e2 = block.e2[i];
    // Transverse inertia about joint k in the plane: S = c1 I + l^2 C^T M C with C = [u]x^T [e1 e2]
    // = [-e2, e1]; c1 is the link's own (translation integral plus thickness).
    const Vec3 m_e1 = child * e1, m_e2 = child * e2;
    const double l2 = l * l, c1 = block.own_transverse[i];
    const double s_a = c1 + l2 * dot(e2, m_e2), s_b = -l2 * dot(e1, m_e2), s_d = c1 + l2 * dot(e1, m_e1);
    // Coupling of the base-end acceleration to the transverse ones: W = E C with E = l^2/2 m' I + l M
    // (A [u]x = (m' + m_a') [u]x for A = m' I + m_a' (I - u u^T)).
    const double half = block.half_moment[i];
    const Vec3 w1 = -(l * m_e2 + half * e2);
    const Vec3 w2 = l * m_e1 + half * e1;
    const double inv_det = 1.0 / (s_a * s_d - s_b * s_b);
    const double s11 = s_d * inv_det, s12 = -s_b * inv_det, s22 = s_a * inv_det;
    const Vec3 x1 = s11 * w1 + s12 * w2;  // X = W S^-1
    const Vec3 x2 = s12 * w1 + s22 * w2;
    // M_k = l A + M_{k+1} - X W^T, its six entries.
    const Symmetric3 own = block.own_mass[i];
    const Symmetric3 m = {own.xx + child.xx - (x1.x * w1.x + x2.x * w2.x),
                          own.xy + child.xy - (x1.x * w1.y + x2.x * w2.y),
                          own.xz + child.xz - (x1.x * w1.z + x2.x * w2.z),
                          own.yy + child.yy - (x1.y * w1.y + x2.y * w2.y),
                          own.yz + child.yz - (x1.y * w1.z + x2.y * w2.z),
                          own.zz + child.zz - (x1.z * w1.z + x2.z * w2.z)};
    // Bias force l^2/2 A beta - F + M_{k+1} l beta + f_{k+1}, and torque about joint k u x h + q with
    // h = l^3/3 m' beta - (first moment of F) + l (M_{k+1} l beta + f_{k+1}).
    const Vec3 passed = l * (child * block.beta[i]) + child_force;
    const Vec3 h = block.own_moment[i] + l * passed;
    const double g1 = block.q1[i] - dot(e2, h), g2 = block.q2[i] + dot(e1, h);
    const Vec3 force = block.own_force[i] + passed - (g1 * x1 + g2 * x2);
    block.mass.set(i, m);
    block.bias.set(i, force);
    block.x1.set(i, x1);
    block.x2.set(i, x2);
    block.y1[i] = -(s11 * g1 + s12 * g2);
    block.y2[i] = -(s12 * g1 + s22 * g2);
    child = m;
    child_force = force;
  }
  // Forward: accelerations from the base outwards; the base translates without turning.
  Vec3 acc = toVec3(links_.get(&LinkBlock::known_acc, 0));
  double added_mass_power = 0.0;
  for (int k = 0; k < n; ++k) {
    const LinkBlock& block = links_.of(k);
    const int i = LinkBlocks::lane(k);
    if (all_joint_forces || k == 0) joint_force_.col(k) = toEigen(block.mass[i] * acc + block.bias[i]);
    // Transverse angular accelerations in the (e1, e2) basis: y = -S^-1 (W^T a_k + g) = -X^T a_k + y_g.
    const double y1 = block.y1[i] - dot(block.x1[i], acc), y2 = block.y2[i] - dot(block.x2[i], acc);
    const Vec3 e1 = block.e1[i], e2 = block.e2[i];
    const Vec3 omega_rate = y1 * e1 + y2 * e2 + block.spin_acc[i] * block.u[i];
    rhs_.segment<3>(3 * k) << omega_rate.x, omega_rate.y, omega_rate.z;
    // u_k'' = omega_k' x u_k + beta_k, with omega' x u = C y = y2 e1 - y1 e2.
    const Vec3 axis_acc = y2 * e1 - y1 * e2 + block.beta[i];
    added_mass_power += dot(block.added_base[i], acc) + dot(block.added_axis[i], axis_acc);
    acc = acc + block.length[i] * axis_acc;
  }
  added_mass_power_ = added_mass_power;
  load_force_ = load_inertia_ * toEigen(acc) - load_external_;
}

}  // namespace cable_dynamics
