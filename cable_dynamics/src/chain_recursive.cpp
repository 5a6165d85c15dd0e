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
EIGEN_ALWAYS_INLINE void normalPlaneBasis(const Eigen::Vector3d& u, Eigen::Vector3d& e1, Eigen::Vector3d& e2) {
  const double sign = std::copysign(1.0, u.z());
  const double a = -1.0 / (sign + u.z());
  const double b = u.x() * u.y() * a;
  e1 << 1.0 + sign * u.x() * u.x() * a, sign * b, -sign * u.x();
  e2 << b, sign + u.y() * u.y() * a, -u.y();
}

}  // namespace

void ChainDynamics::allocateRecursion() {
  articulated_.assign(n_, ArticulatedLink{});
  constants_.resize(n_);
  for (int k = 0; k < n_; ++k) {
    LinkConstants& c = constants_[k];
    const double l = props_.length(k);
    c.length = l;
    c.added = added_per_length_(k);
    c.across = mass_per_length_(k) + c.added;
    c.half_moment = 0.5 * l * l * c.across;
    c.third_moment = l * l * l / 3.0 * c.across;
    c.own_transverse = c.third_moment + thick_transverse_(k);
    c.inverse_polar = 1.0 / props_.inertia_polar(k);
    c.gyroscopic = props_.inertia_polar(k) - thick_transverse_(k);
  }
}

CABLE_HOT_PATH void ChainDynamics::solveRecursive(bool all_joint_forces) {
  const int n = n_;
  // What each link contributes on its own: its plane basis, inertia and bias (velocity terms: the
  // centripetal beta = u'' at zero angular acceleration and the gyroscopic torque, minus the external
  // forces). Kept apart from the backward pass so that its loop holds little more than M and f.
  for (int k = 0; k < n; ++k) {
    ArticulatedLink& link = articulated_[k];
    const LinkConstants& c = constants_[k];
    const Eigen::Vector3d u = u_.col(k), beta = beta_.col(k);
    normalPlaneBasis(u, link.e1, link.e2);
    // l A = l m' I + l m_a' (I - u u^T).
    const double lm = c.length * c.across, la = c.length * c.added;
    link.own_mass = {lm - la * u.x() * u.x(), -la * u.x() * u.y(), -la * u.x() * u.z(),
                     lm - la * u.y() * u.y(), -la * u.y() * u.z(), lm - la * u.z() * u.z()};
    const Eigen::Vector3d a_beta = c.across * beta - c.added * u.dot(beta) * u;
    link.own_force = (0.5 * c.length * c.length) * a_beta - force_.col(k);
    link.own_moment = c.third_moment * beta - moment_.col(k);
    // omega x (I_rot omega) - tau, with I_rot = I_thick (I - u u^T) + I_P u u^T.
    const Eigen::Vector3d q = (c.gyroscopic * u.dot(omega_.col(k))) * axis_rate_.col(k) - torque_.col(k);
    link.q1 = link.e1.dot(q);
    link.q2 = link.e2.dot(q);
    addedMassPowerWeights(c.added, c.length, u, axis_rate_.col(k), base_vel_.col(k), link.added_base, link.added_axis);
  }
  // Backward: from the load inwards, fold everything outboard of joint k into (M_k, f_k).
  // The load is a point mass at the tip: J_n = m_L a_n - F_L.
  Symmetric3 child = Symmetric3::scaledIdentity(load_inertia_);
  Eigen::Vector3d child_force = -load_external_;
  for (int k = n - 1; k >= 0; --k) {
    ArticulatedLink& link = articulated_[k];
    const LinkConstants& c = constants_[k];
    const double l = c.length;
    const Eigen::Vector3d e1 = link.e1, e2 = link.e2;
    // Transverse inertia about joint k in the plane: S = c1 I + l^2 C^T M C with C = [u]x^T [e1 e2]
    // = [-e2, e1]; c1 is the link's own (translation integral plus thickness).
    const Eigen::Vector3d m_e1 = child * e1, m_e2 = child * e2;
    const double l2 = l * l;
    const double s_a = c.own_transverse + l2 * e2.dot(m_e2), s_b = -l2 * e1.dot(m_e2),
                 s_d = c.own_transverse + l2 * e1.dot(m_e1);
    // Coupling of the base-end acceleration to the transverse ones: W = E C with E = l^2/2 m' I + l M
    // (A [u]x = (m' + m_a') [u]x for A = m' I + m_a' (I - u u^T)).
    const Eigen::Vector3d w1 = -(l * m_e2 + c.half_moment * e2);
    const Eigen::Vector3d w2 = l * m_e1 + c.half_moment * e1;
    const double inv_det = 1.0 / (s_a * s_d - s_b * s_b);
    const double s11 = s_d * inv_det, s12 = -s_b * inv_det, s22 = s_a * inv_det;
    const Eigen::Vector3d x1 = s11 * w1 + s12 * w2;  // X = W S^-1
    const Eigen::Vector3d x2 = s12 * w1 + s22 * w2;
    // M_k = l A + M_{k+1} - X W^T, its six entries.
    const Symmetric3& own = link.own_mass;
    Symmetric3& m = link.mass;
    m.xx = own.xx + child.xx - (x1.x() * w1.x() + x2.x() * w2.x());
    m.xy = own.xy + child.xy - (x1.x() * w1.y() + x2.x() * w2.y());
    m.xz = own.xz + child.xz - (x1.x() * w1.z() + x2.x() * w2.z());
    m.yy = own.yy + child.yy - (x1.y() * w1.y() + x2.y() * w2.y());
    m.yz = own.yz + child.yz - (x1.y() * w1.z() + x2.y() * w2.z());
    m.zz = own.zz + child.zz - (x1.z() * w1.z() + x2.z() * w2.z());
    // Bias force l^2/2 A beta - F + M_{k+1} l beta + f_{k+1}, and torque about joint k u x h + q with
    // h = l^3/3 m' beta - (first moment of F) + l (M_{k+1} l beta + f_{k+1}).
    const Eigen::Vector3d passed = l * (child * beta_.col(k)) + child_force;
    const Eigen::Vector3d h = link.own_moment + l * passed;
    const double g1 = link.q1 - e2.dot(h), g2 = link.q2 + e1.dot(h);
    link.force = link.own_force + passed - (g1 * x1 + g2 * x2);
    link.x1 = x1;
    link.x2 = x2;
    link.y1 = -(s11 * g1 + s12 * g2);
    link.y2 = -(s12 * g1 + s22 * g2);
    child = m;
    child_force = link.force;
  }
  // Forward: accelerations from the base outwards; the base translates without turning.
  Eigen::Vector3d acc = known_acc_.col(0);
  added_mass_power_ = 0.0;
  for (int k = 0; k < n; ++k) {
    const ArticulatedLink& link = articulated_[k];
    const LinkConstants& c = constants_[k];
    if (all_joint_forces || k == 0) joint_force_.col(k) = link.mass * acc + link.force;
    // Transverse angular accelerations in the (e1, e2) basis: y = -S^-1 (W^T a_k + g) = -X^T a_k + y_g.
    const double y1 = link.y1 - link.x1.dot(acc), y2 = link.y2 - link.x2.dot(acc);
    const Eigen::Vector3d u = u_.col(k);
    // Spin: I_P (omega'.u) = tau.u, since a spherical joint passes no torque along the link.
    const double spin_acc = c.inverse_polar * u.dot(torque_.col(k));
    rhs_.segment<3>(3 * k) = y1 * link.e1 + y2 * link.e2 + spin_acc * u;
    // u_k'' = omega_k' x u_k + beta_k, with omega' x u = C y = y2 e1 - y1 e2.
    const Eigen::Vector3d axis_acc = y2 * link.e1 - y1 * link.e2 + beta_.col(k);
    added_mass_power_ += link.added_base.dot(acc) + link.added_axis.dot(axis_acc);
    acc += c.length * axis_acc;
  }
  load_force_ = load_inertia_ * acc - load_external_;
}

}  // namespace cable_dynamics
