#pragma once
/// \file
/// \brief The seabed's contact law at one point (docs/MODEL.md section 10): its value (force and the power
///        it dissipates), its potential energy, its Jacobian (for the implicit step) and its form at rest
///        (for the statics), side by side. The bed's geometry (where a point is, how deep, the normal)
///        is Seabed's; the passes over the links and the load are seabed_contact.cpp (explicit),
///        stiff_articulated_body.cpp (the linearization) and static_equations.cpp (the statics), and
///        all of them read the law from here.
///
/// The law, for a point standing for `share` metres of cable (1 for the load) at penetration delta > 0
/// with the bed's inward normal n, moving at v: a normal spring-damper
///   N = max(0, share k delta + share c ramp delta'),  ramp = min(1, delta / rest),  delta' = v . n,
/// (the damper ramps in over the resting penetration, so that the force is continuous at touchdown, and
/// the bed only pushes), and Coulomb friction with static friction: on the slip s = v - delta' n and the
/// point's tangential offset d from its anchor on the bed (d = P (p - anchor), P = I - n n^T),
///   w = d / x_b + s / v_r,   f = -N / max(|w|, 1) (mu_a (w.a) a + mu_l (w - (w.a) a)),
/// with a the unit direction of the link's axis along the bed (isotropic at mu_l where there is none: the
/// load, a link standing on end). The force on the point is -N n + f. Below breakout (|w| < 1) the anchor
/// holds the point with a spring mu N / x_b and a damper mu N / v_r: it sticks; at |w| = 1 the friction is
/// mu N, Coulomb's, and the anchor slides after the step (seabed_contact.h, placeContactAnchors), keeping
/// |d| <= x_b. This is the anchor-spring ("bristle") model OrcaFlex's seabed friction uses. With no anchor
/// (x_b = 0: seabed.friction.breakout 0) w = s / v_r and the law is the regularized Coulomb friction
///   f = -N / max(|s|, v_r) (mu_a (s.a) a + mu_l (s - (s.a) a)),
/// which creeps at v_r tan(slope) / mu on any slope.

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "cable_dynamics/dynamics/link_block.h"

namespace cable_dynamics {

/// The law's coefficients for one point: its share of the spring k and damper c (per share), the resting
/// penetration over which the damper ramps in, and the friction's (from SeabedContactConstants).
struct ContactLaw {
  double stiffness = 0.0;  ///< share k [N/m]
  double damping = 0.0;    ///< share c [N s/m]
  double rest = 1.0;       ///< the damper's ramp length [m]
  double friction_axial = 0.0, friction_lateral = 0.0;  ///< Coulomb coefficients [-]
  double friction_velocity = 0.01;  ///< regularization speed v_r [m/s]
  double friction_breakout = 0.0;   ///< x_b, the anchor's reach before the point slides [m]; 0: no anchor

  bool hasFriction() const { return friction_axial > 0.0 || friction_lateral > 0.0; }
};

/// Where a point is against the bed: its penetration (> 0 in contact) [m], the bed's unit inward normal,
/// the unit direction of the link's axis along the bed (`has_along` false: none, isotropic friction).
struct ContactPlace {
  double delta = 0.0;
  Vec3 normal{0.0, 0.0, 1.0};
  Vec3 along{0.0, 0.0, 0.0};
  bool has_along = false;
  /// The point less its friction anchor (p - anchor) [m]; zero without static friction.
  Vec3 offset{0.0, 0.0, 0.0};
};

/// The friction's anchors, one per contact point (static friction; forces/contact.h): where each point's
/// anchor spring is fixed on the bed, moved only between steps (placeContactAnchors, seabed_contact.h).
struct ContactAnchors {
  Eigen::Matrix3Xd link;  ///< (3 x n K) anchor of point j of link k in column k K + j, paper frame [m]
  /// (n) whether link k's anchors are placed; not (a link wholly above the bed at the last placing): its
  /// points have no offset, as if each anchor were on its point.
  std::vector<char> placed;
  Eigen::Vector3d load = Eigen::Vector3d::Zero();  ///< the load's [m]
  int points = 0;         ///< K, contact points per link

  bool active() const { return points > 0; }
  void allocate(int links, int per_link) {
    points = per_link;
    link.setZero(3, links * per_link);
    placed.assign(links, 0);
  }
  /// Link k's K anchors (3 K, point after point), or null where it has none placed.
  const double* of(int k) const { return points > 0 && placed[k] ? link.col(k * points).data() : nullptr; }
  /// The offset p - anchor of point j at `point` [m] from its anchor in `anchors` (a link's, from of()).
  static Vec3 offset(const double* anchors, int j, const Vec3& point) {
    return point - Vec3{anchors[3 * j], anchors[3 * j + 1], anchors[3 * j + 2]};
  }
  /// The load's offset from its anchor [m] (zero without static friction).
  Vec3 loadOffset(const Eigen::Vector3d& tip) const {
    return active() ? toVec3(Eigen::Vector3d(tip - load)) : Vec3{0.0, 0.0, 0.0};
  }
};

/// The unit direction along the bed (normal n) of an axis [-]; false when the axis is (nearly) normal to it.
EIGEN_ALWAYS_INLINE bool alongTheBed(const Vec3& axis, const Vec3& n, Vec3& along) {
  const Vec3 projected = axis - dot(axis, n) * n;
  const double squared = dot(projected, projected);
  if (squared <= 1e-12) return false;
  along = (1.0 / std::sqrt(squared)) * projected;
  return true;
}

/// The friction's dimensionless argument w = d / x_b + s / v_r (forces/contact.h's law) at slip s [m/s],
/// with d the tangential part of place.offset; s / v_r alone without an anchor (x_b = 0).
EIGEN_ALWAYS_INLINE Vec3 frictionArgument(const ContactLaw& law, const ContactPlace& place, const Vec3& slip) {
  Vec3 w = (1.0 / law.friction_velocity) * slip;
  if (law.friction_breakout > 0.0) {
    const Vec3 d = place.offset - dot(place.offset, place.normal) * place.normal;
    w = w + (1.0 / law.friction_breakout) * d;
  }
  return w;
}

/// One contact point's force [N] (paper frame) and the power it dissipates [W] (>= 0: the damper and
/// the friction; what the spring does not store).
struct PointContact {
  Vec3 force{0.0, 0.0, 0.0};
  double dissipation = 0.0;
  double penetration = 0.0;  ///< [m]
};

/// The normal force N [N] at penetration delta [m] and penetration rate [m/s] (>= 0: the bed only pushes).
EIGEN_ALWAYS_INLINE double contactNormalForce(const ContactLaw& law, double delta, double rate) {
  const double ramp = std::min(1.0, delta / law.rest);
  return std::max(0.0, law.stiffness * delta + law.damping * ramp * rate);
}

/// The law's value at a point in contact (place.delta > 0) moving at v [m/s]. Inline: it runs for every
/// contact point of every evaluation.
EIGEN_ALWAYS_INLINE void contactForce(const ContactLaw& law, const ContactPlace& place, const Vec3& v, PointContact& out) {
  const Vec3 n = place.normal;
  const double rate = dot(v, n);  // penetration rate [m/s]
  const double spring = law.stiffness * place.delta;
  const double normal = contactNormalForce(law, place.delta, rate);
  Vec3 force = -normal * n;
  // What the spring does not store is dissipated: (N - k delta share) delta' >= 0 (the damper's
  // c ramp delta'^2 share, or, when the bed lets go, -k delta delta' share with delta' < 0).
  double dissipation = (normal - spring) * rate;
  if (normal > 0.0 && law.hasFriction()) {
    const Vec3 slip = v - rate * n;  // in the bed's tangent plane
    const Vec3 w = frictionArgument(law, place, slip);
    // Coulomb at and beyond breakout, a spring and damper to the anchor below it (continuous).
    const double scale = normal / std::max(std::sqrt(dot(w, w)), 1.0);
    Vec3 friction;
    if (place.has_along) {
      const Vec3 axial = dot(w, place.along) * place.along;
      friction = -scale * (law.friction_axial * axial + law.friction_lateral * (w - axial));
    } else {
      friction = -(scale * law.friction_lateral) * w;
    }
    force = force + friction;
    // The friction's power: what it takes out sliding; while the point sticks its anchor spring gives back
    // what it stored, so this can be negative for a while (the balance integrates it either way).
    dissipation -= dot(friction, slip);
  }
  out.force = force;
  out.dissipation = dissipation;
  out.penetration = place.delta;
}

/// The contact spring's potential energy at penetration delta > 0 [J]: 1/2 share k delta^2.
inline double contactEnergy(const ContactLaw& law, double delta) { return 0.5 * law.stiffness * delta * delta; }

/// The law's Jacobian at a point in contact moving at v [m/s], in factored form: the normal spring share k
/// and damper share c ramp along n n^T [N/m], [N s/m], and the friction's secant N / max(|w|, 1) [N] (0 where
/// the point does not press or there is no friction), which multiplies the tangent pattern
/// (frictionPattern) over x_b in the stiffness and over v_r in the damping (w has 1 / v_r per unit of slip
/// speed and 1 / x_b per unit of offset from the anchor). contactJacobian assembles it per point; on a
/// flat bed, where a link's points share n and the pattern, the implicit step sums the three scalars over
/// the points and assembles once per link (stiff_articulated_body.cpp, linearizeContact).
struct ContactJacobianParts {
  double normal_stiffness = 0.0, normal_damping = 0.0, friction_secant = 0.0;
};

EIGEN_ALWAYS_INLINE ContactJacobianParts contactJacobianParts(const ContactLaw& law, const ContactPlace& place,
                                                             const Vec3& v) {
  ContactJacobianParts j;
  const double rate = dot(v, place.normal), ramp = std::min(1.0, place.delta / law.rest);
  const double normal = contactNormalForce(law, place.delta, rate);
  j.normal_stiffness = law.stiffness;
  j.normal_damping = law.damping * ramp;
  if (normal > 0.0 && law.hasFriction()) {
    const Vec3 w = frictionArgument(law, place, v - rate * place.normal);
    j.friction_secant = normal / std::max(std::sqrt(dot(w, w)), 1.0);
  }
  return j;
}

/// The friction's coefficients over the bed's tangent plane per unit of w, mu_a a a^T + mu_l (P - a a^T)
/// with P = I - n n^T and a the axis's direction along the bed (mu_l P where it has none) [-].
inline Eigen::Matrix3d frictionPattern(const ContactLaw& law, const ContactPlace& place) {
  const Eigen::Vector3d n = toEigen(place.normal);
  const Eigen::Matrix3d tangent = Eigen::Matrix3d::Identity() - n * n.transpose();
  if (!place.has_along) return law.friction_lateral * tangent;
  const Eigen::Vector3d a = toEigen(place.along);
  const Eigen::Matrix3d aa = a * a.transpose();
  return law.friction_axial * aa + law.friction_lateral * (tangent - aa);
}

/// The law's Jacobian at one point: the stiffness -dF/dx ~ share k n n^T (the bed's curvature and the
/// damper's ramp left out) plus the friction's anchor spring, and the damping -dF/dv ~ share c ramp n n^T
/// plus the friction's damper (contactJacobianParts: below breakout, the stiff part, exactly; beyond it the
/// secant, not the tangent). Both are exact where the point does not slip, the ramp is full
/// (delta >= rest) and the bed is flat (test_force_modules). An approximation elsewhere is what the
/// implicit step's W-method allows: it costs no order.
inline void contactJacobian(const ContactLaw& law, const ContactPlace& place, const Eigen::Vector3d& v,
                            Eigen::Matrix3d& stiffness, Eigen::Matrix3d& damping) {
  const ContactJacobianParts parts = contactJacobianParts(law, place, toVec3(v));
  const Eigen::Vector3d n = toEigen(place.normal);
  const Eigen::Matrix3d nn = n * n.transpose();
  stiffness = parts.normal_stiffness * nn;
  damping = parts.normal_damping * nn;
  if (parts.friction_secant > 0.0) {
    const Eigen::Matrix3d pattern = frictionPattern(law, place);
    damping += (parts.friction_secant / law.friction_velocity) * pattern;
    if (law.friction_breakout > 0.0) stiffness += (parts.friction_secant / law.friction_breakout) * pattern;
  }
}

/// The law at rest, for the statics: the spring's force -share k delta n [N]. No damper (v = 0) and no
/// friction: the statics solve the equilibrium without it, one of the equilibria the friction allows, and
/// the anchors are then placed there.
inline Eigen::Vector3d contactForceAtRest(const ContactLaw& law, const ContactPlace& place) {
  return -(law.stiffness * place.delta) * toEigen(place.normal);
}

}  // namespace cable_dynamics
