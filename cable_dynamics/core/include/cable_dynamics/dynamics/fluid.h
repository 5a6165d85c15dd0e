#pragma once
/// \file
/// \brief The water around the cable: current (uniform or a depth profile) and the links' Morison drag, the
///        drag's module: its value and power (LinkDrag::addUniform, in SIMD lanes; pointwise), its form at
///        rest (pointwise at zero velocity, the statics') and its Jacobian (LinkDrag::damping), side by side.

#include <algorithm>
#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross()

#include "cable_dynamics/params/cable_params.h"
#include "cable_dynamics/dynamics/forces/point_drag.h"  // the points' drag (attachments, the load)
#include "cable_dynamics/dynamics/link_block.h"

namespace cable_dynamics {

/// Current velocity as a function of depth, in the paper frame (z down) [m/s].
class CurrentField {
 public:
  explicit CurrentField(const FluidParams& fluid);

  /// Current at paper-frame depth z below the base [m]: linear in the profile, constant beyond it.
  Eigen::Vector3d at(double z) const;

  /// Replaces the field by a uniform current given in the world frame [m/s] (e.g. from a topic).
  void setUniformWorld(const Eigen::Vector3d& current_world);

  /// true when the current is the same at every depth (no profile).
  bool uniform() const { return depth_.size() == 0; }

  /// The current when uniform() [m/s].
  const Eigen::Vector3d& uniformValue() const { return uniform_; }

 private:
  Eigen::Vector3d uniform_;                   ///< paper frame [m/s]
  Eigen::VectorXd depth_;                     ///< (rows) [m]
  Eigen::Matrix3Xd profile_;                  ///< (3 x rows) paper frame [m/s]
};

/// Morison drag per unit length on a cylinder of diameter d with axis u, moving at velocity `velocity`
/// through water moving at `current` (both [m/s]): normal part 1/2 rho C_n d |v_n| v_n on the projected
/// diameter, tangential part 1/2 rho C_t (pi d) |v_t| v_t on the wetted perimeter, v = current - velocity.
/// Returns [N/m].
Eigen::Vector3d morisonDragPerLength(const Eigen::Vector3d& axis, const Eigen::Vector3d& velocity,
                                     const Eigen::Vector3d& current, double density, double diameter,
                                     double drag_normal, double drag_tangential);

/// Power of the normal added-mass force on a link [W] as base_weight.a + axis_weight.u'' for its base-end
/// acceleration a and axis acceleration u'': the force per length -m_a' P x'' (P = I - u u^T) against
/// the velocity x' = v + s u', integrated over the length l. With x'' = a + s u'' and P x' = P v + s u'
/// (u' is normal to u) it is -m_a' [l a.Pv + l^2/2 (a.u' + u''.Pv) + l^3/3 u''.u'].
/// added_per_length m_a' [kg/m], l [m], unit axis u, axis_rate u' [1/s], velocity v [m/s].
EIGEN_ALWAYS_INLINE void addedMassPowerWeights(double added_per_length, double l, const Vec3& u, const Vec3& axis_rate,
                                  const Vec3& velocity, Vec3& base_weight, Vec3& axis_weight) {
  const Vec3 normal_velocity = velocity - dot(u, velocity) * u;
  base_weight = -added_per_length * (l * normal_velocity + (0.5 * l * l) * axis_rate);
  axis_weight = -added_per_length * ((0.5 * l * l) * normal_velocity + (l * l * l / 3.0) * axis_rate);
}

/// Morison coefficients of one link: per length the drag is normal |v_n| v_n + tangential |v_t| v_t.
struct DragCoefficients {
  double normal = 0.0;      ///< 1/2 rho C_n d [kg/m^2]
  double tangential = 0.0;  ///< 1/2 rho C_t pi d [kg/m^2]
};

/// addedMassPowerWeights() for lane i of `c`, with its attachments' isotropic added mass: a point at s_p
/// moves at v + s_p u' and accelerates at a + s_p u'', so the force -m_pa (a + s_p u'') has the power
/// -(sum m_pa (v + s_p u')).a - (sum m_pa s_p (v + s_p u')).u''.
EIGEN_ALWAYS_INLINE void linkAddedMassPowerWeights(const LinkConstants& c, int i, const Vec3& u, const Vec3& axis_rate,
                                      const Vec3& velocity, Vec3& base_weight, Vec3& axis_weight) {
  addedMassPowerWeights(c.added[i], c.length[i], u, axis_rate, velocity, base_weight, axis_weight);
  base_weight = base_weight - (c.point_added0[i] * velocity + c.point_added1[i] * axis_rate);
  axis_weight = axis_weight - (c.point_added1[i] * velocity + c.point_added2[i] * axis_rate);
}

/// Gauss-Legendre nodes on [0, 1] and their weights (sum 1), for 1 to 8 points.
void gaussLegendreUnit(int points, double* nodes, double* weights);

/// Morison drag integrated along straight links by Gauss-Legendre quadrature (fluid.drag_points points).
class LinkDrag {
 public:
  /// The quadrature (fluid.drag_points); the coefficients are per link (LinkConstants, sections).
  explicit LinkDrag(const FluidParams& fluid);

  int points() const { return points_; }

  /// 1/2 rho C_n d and 1/2 rho C_t pi d for a cylinder of diameter d [m] in a fluid of density rho [kg/m^3].
  static DragCoefficients coefficients(double density, double diameter, double drag_normal, double drag_tangential) {
    return {0.5 * density * diameter * drag_normal, 0.5 * density * diameter * drag_tangential * M_PI};
  }

  /// Adds the drag in a current that is the same at every depth [m/s] to the eight links of `block`
  /// (their lengths and drag coefficients from `constants`; base_vel, u and axis_rate from `block`): the force [N] to `force`, its first moment about the base
  /// end, the integral of s f(s) ds [N m], to `moment` (the torque about the base end is u x moment), and
  /// sets `drag_power` [W]. With one current c the relative water velocity is c - v - s u', and u' is
  /// normal to u: its tangential part (c - v).u is the same at every s, and its normal part is n0 - s u'
  /// with |n0 - s u'|^2 quadratic in s. So the quadrature needs one square root per point, and the
  /// force and moment are n0 and u' weighted by sums of w |n(s)|, w s |n(s)| and w s^2 |n(s)|. Each
  /// loop runs over the block's lanes and compiles to vector instructions. Inline: it runs for every
  /// link in every evaluation.
  EIGEN_ALWAYS_INLINE void addUniform(const Vec3& current, const LinkConstants& constants, LinkBlock& block) const {
    double c0[kBlockLanes], c1[kBlockLanes], c2[kBlockLanes], along[kBlockLanes];
    Lanes3 normal;
    for (int i = 0; i < kBlockLanes; ++i) {
      const Vec3 relative = current - block.base_vel[i], axis = block.u[i], axis_rate = block.axis_rate[i];
      along[i] = dot(relative, axis);
      const Vec3 n0 = relative - along[i] * axis;
      normal.set(i, n0);
      c0[i] = dot(n0, n0);
      c1[i] = -2.0 * dot(n0, axis_rate);
      c2[i] = dot(axis_rate, axis_rate);
    }
    double sum0[kBlockLanes] = {}, sum1[kBlockLanes] = {}, sum2[kBlockLanes] = {};
    for (int p = 0; p < points_; ++p) {
      const double node = nodes_[p], weight = weights_[p];
      for (int i = 0; i < kBlockLanes; ++i) {
        const double l = constants.length[i], s = node * l, w = weight * l;
        const double speed_squared = c0[i] + s * (c1[i] + s * c2[i]);  // |n(s)|^2; round-off can dip below 0
        const double speed = std::sqrt(std::max(speed_squared, 0.0));
        sum0[i] += w * speed;
        sum1[i] += (w * s) * speed;
        sum2[i] += (w * s * s) * speed;
      }
    }
    CABLE_LANE_LOOP
    for (int i = 0; i < kBlockLanes; ++i) {
      const double l = constants.length[i];
      const Vec3 axis = block.u[i], axis_rate = block.axis_rate[i], n0 = normal[i];
      const double normal_coefficient = constants.drag_normal[i];
      const double tangential = constants.drag_tangential[i] * std::abs(along[i]) * along[i] * l;  // [N]
      const Vec3 force = normal_coefficient * (sum0[i] * n0 - sum1[i] * axis_rate) + tangential * axis;
      const Vec3 moment = normal_coefficient * (sum1[i] * n0 - sum2[i] * axis_rate) + (0.5 * l * tangential) * axis;
      block.force.set(i, block.force[i] + force);
      block.moment.set(i, block.moment[i] + moment);
      block.drag_power[i] = dot(force, block.base_vel[i]) + dot(moment, axis_rate);
    }
  }

  /// Drag on a link of length l [m] and coefficients `coefficients` with base end at `base` [m] moving at `velocity` [m/s], unit axis u
  /// turning at u' = `axis_rate` [1/s], by the same quadrature evaluated point by point with the current
  /// at each point's depth: the total force [N] and its first moment about the base end [N m]. What
  /// a depth profile needs, and the reference the tests hold addUniform() against.
  void pointwise(const CurrentField& current, double l, const DragCoefficients& coefficients,
                 const Eigen::Vector3d& base, const Eigen::Vector3d& velocity,
                 const Eigen::Vector3d& axis, const Eigen::Vector3d& axis_rate, Eigen::Vector3d& force,
                 Eigen::Vector3d& moment) const;

  /// The drag's damping over the link's (omega, v_base), the implicit step's Jacobian (stiff_articulated_body.h):
  /// torque about the base end per omega `rr` [N m s], per v_base `rv` [N s], force per v_base `vv` [N s/m]
  /// (force per omega is rv^T), for a link of length l [m], unit axis u turning at u' = `axis_rate` [1/s],
  /// with `relative` = current - v_base [m/s] (the current taken at the link's middle: a Jacobian, where an
  /// approximation costs the W-method no order).
  /// Per length f = c_n |v_n| v_n + c_t |v_t| v_t with v = current - velocity, whose derivative with respect
  /// to the structure's velocity is -C, C = c_n (|v_n| P + v_n v_n^T / |v_n|) + 2 c_t |v.u| u u^T. A point at
  /// s moves at v_base + s omega x u = v_base - s [u]x omega: with C0, C1, C2 the integrals of C, s C, s^2 C,
  /// the damping is [[-[u]x C2 [u]x, [u]x C1], [-C1 [u]x, C0]]. With the current at the middle, v.u = along
  /// is the same all along the link and v_n(s) = n0 - s u' (u' normal to u), so each C_m is
  /// A_m P + b W_m u u^T + G_m n0 n0^T - G_{m+1} (n0 u'^T + u' n0^T) + G_{m+2} u' u'^T with the quadrature's
  /// sums W_m of w s^m, A_m of w s^m c_n |v_n|, G_m of w s^m c_n / |v_n|, b = 2 c_t |along|. Exact (to the
  /// quadrature) in a uniform current (test_implicit_recursion, test_force_modules).
  EIGEN_ALWAYS_INLINE void damping(double l, const DragCoefficients& coefficients, const Eigen::Vector3d& u,
                                   const Eigen::Vector3d& relative, const Eigen::Vector3d& rate, Eigen::Matrix3d& rr,
                                   Eigen::Matrix3d& rv, Eigen::Matrix3d& vv) const {
    const double cn = coefficients.normal, ct = coefficients.tangential;
    const double along = relative.dot(u);
    const Eigen::Vector3d n0 = relative - along * u;
    double w[3] = {0.0, 0.0, 0.0}, a[3] = {0.0, 0.0, 0.0}, g[5] = {0.0, 0.0, 0.0, 0.0, 0.0};
    for (int q = 0; q < points_; ++q) {
      const double s = nodes_[q] * l, weight = weights_[q] * l;
      const double speed = (n0 - s * rate).norm();
      const double inverse = speed > 1e-12 ? cn / speed : 0.0;
      double power = weight;  // w s^m
      for (int m = 0; m < 5; ++m) {
        if (m < 3) {
          w[m] += power;
          a[m] += power * cn * speed;
        }
        g[m] += power * inverse;
        power *= s;
      }
    }
    const double b = 2.0 * ct * std::abs(along);
    const Eigen::Matrix3d uu = u * u.transpose(), P = Eigen::Matrix3d::Identity() - uu;
    const Eigen::Matrix3d nn = n0 * n0.transpose(), nr = n0 * rate.transpose(), rate_rate = rate * rate.transpose();
    // C0 (force per base velocity).
    vv = a[0] * P + (b * w[0]) * uu + g[0] * nn - g[1] * (nr + nr.transpose()) + g[2] * rate_rate;
    // [u]x C1: [u]x u = 0, [u]x P = [u]x.
    const Eigen::Vector3d un = u.cross(n0), ur = u.cross(rate);
    Eigen::Matrix3d cross_u;  // [u]x
    cross_u << 0.0, -u.z(), u.y(), u.z(), 0.0, -u.x(), -u.y(), u.x(), 0.0;
    rv = a[1] * cross_u + g[1] * un * n0.transpose() - g[2] * (un * rate.transpose() + ur * n0.transpose()) +
         g[3] * ur * rate.transpose();
    // [u]x^T C2 [u]x: [u]x^T P [u]x = P, [u]x^T u u^T [u]x = 0, and (u x n)(u x n)^T for n n^T.
    const Eigen::Matrix3d unur = un * ur.transpose();
    rr = a[2] * P + g[2] * un * un.transpose() - g[3] * (unur + unur.transpose()) + g[4] * ur * ur.transpose();
  }

 private:
  int points_;
  double nodes_[8], weights_[8];
};

}  // namespace cable_dynamics
